#pragma once
// A plain folder of 16-bit depth PNGs read as a sequence: no dataset.json, no poses, frames in
// natural name order (frame2.png before frame10.png). Each frame is read as a single depth PNG
// would be: the user's intrinsics and depth scale, else PrimeSense VGA scaled to the image.
#include <string>
#include <vector>

#include "core/io/frame_source.h"

namespace tunnelmap {

// The .png files (any case) directly inside `folder`, sorted in natural order; subfolders and
// other files are ignored. Empty when there are none.
std::vector<std::string> list_depth_pngs(const std::string& folder);

// "a2" < "a10": runs of digits compare by value, everything else byte-wise.
bool natural_less(const std::string& a, const std::string& b);

// A FrameSource over list_depth_pngs(folder). InputError naming the folder when it holds none.
std::unique_ptr<FrameSource> open_png_folder(const std::string& folder, const ReadOptions& opt);

}  // namespace tunnelmap
