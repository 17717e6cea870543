#pragma once
// R&L baseline (paper section 3, after Yoruk 2014 p.59): sequential RANSAC plane extraction
// with a least-squares (PCA) refit of every plane's inliers, repeated `iterations` times with
// different random streams; the segmentation with the lowest squared error wins. The tunnel is
// then fitted to these planes by the same template fitting as PG&C (detect_tunnel).
#include <cstdint>

#include "core/frame/organized_cloud.h"
#include "core/baselines/baseline_options.h"  // RansacLseOptions
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct RansacLseResult {
  PlaneSegments planes;        // PlaneSegment::points = inliers x sample_step^2 (pixels covered)
  double squared_error = 0.0;  // truncated squared error of the winning segmentation (m^2)
  int winning_iteration = 0;
};

// Throws ParameterError for options out of range. `planes.labels` marks the sampled pixels only.
RansacLseResult ransac_lse_planes(const OrganizedCloud& cloud, const RansacLseOptions& options);

}  // namespace tunnelmap
