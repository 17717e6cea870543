#pragma once
// Reader for organised PCD files (PCL format, height > 1): depth = z in metres.
#include <string>

#include "core/frame/depth_frame.h"
#include "core/io/read_options.h"

namespace tunnelmap {

// depth_units_per_m = 1; NaN / non-positive z -> 0. Intrinsics from `opt` (width/height from
// the cloud), else estimated from the points (error asking for --intrinsics if too few).
DepthFrame read_organized_pcd(const std::string& path, const ReadOptions& opt);

}  // namespace tunnelmap
