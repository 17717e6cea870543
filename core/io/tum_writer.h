#pragma once
// Writes a Dataset as a TUM RGB-D sequence: depth/<t>.png at 5000 units per metre, rgb/<t>.png
// (or .jpg, copied), depth.txt, rgb.txt, groundtruth.txt (posed frames) and tunnelmap.json
// (intrinsics, world up, "ground_truth"), where <t> is the frame's timestamp in seconds.
#include <string>

#include "core/io/dataset.h"
#include "core/io/sequence_export.h"

namespace tunnelmap {

// The folder appears whole or not at all (StagedFolder). Depth already at 5000 units per metre
// is copied; other scales are re-encoded (values past 65535 units, 13.1 m, become 0 and are
// noted). Timestamps that do not increase at microsecond precision are replaced by 1/30 s steps
// (noted). Frames are loaded and validated first: InputError as Dataset::load_frame.
void write_tum_sequence(const Dataset& ds, const std::string& out_dir, const SequenceExport& ex);

// True for a folder this writer made (depth.txt and tunnelmap.json): simulate may replace it.
bool is_tunnelmap_tum_sequence(const std::filesystem::path& dir);

}  // namespace tunnelmap
