#pragma once
// Stage 2a: back-projects a DepthFrame into an organised point cloud (camera frame, metres).
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/frame/organized_cloud.h"
#include "core/normals/cloud_options.h"  // CloudOptions

namespace tunnelmap {

// The per-column and per-row ray factors build_cloud computes, kept by the caller (one per
// concurrent caller) so that frame after frame allocates nothing.
struct CloudScratch {
  std::vector<float> kx, ky;  // x = kx[u] * z, y = ky[v] * z
};

// Fills cloud.points (NaN outside [min_range, max_range] or where depth is 0/NaN/inf).
// Reuses cloud's and scratch's buffers when the size matches (no per-frame allocation in the
// steady state).
void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud,
                 CloudScratch& scratch);
// The same with scratch of its own: allocates it on every call (one-off frames, tests).
void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud);

}  // namespace tunnelmap
