#pragma once
// Stage 2a: back-projects a DepthFrame into an organised point cloud (camera frame, metres).
#include "core/frame/depth_frame.h"
#include "core/frame/organized_cloud.h"

namespace tunnelmap {

struct CloudOptions {
  double min_range_m = 0.3;  // cloud.min_range_m
  double max_range_m = 5.0;  // cloud.max_range_m
};

// Fills cloud.points (NaN outside [min_range, max_range] or where depth is 0/NaN/inf).
// Reuses cloud's buffers when the size matches (no per-frame allocation in the steady state).
void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud);

}  // namespace tunnelmap
