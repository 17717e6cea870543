#pragma once
// R&L baseline (paper section 3, after Yoruk 2014 p.59): sequential RANSAC plane extraction
// with a least-squares (PCA) refit of every plane's inliers, repeated `iterations` times with
// different random streams; the segmentation with the lowest squared error wins. The tunnel is
// then fitted to these planes by the same template fitting as PG&C (detect_tunnel).
#include <cstdint>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct RansacLseOptions {
  int iterations = 100;        // whole RANSAC + LSE segmentations (paper: 100)
  int sample_step = 1;         // every step-th pixel in u and v (1: the whole frame, as the paper)
  double distance_m = 0.015;   // inlier band, the paper's point-to-plane distance
  int max_planes = 8;          // planes extracted per segmentation
  int min_plane_points = 40;   // sampled points; fewer inliers end the extraction
  int max_trials = 1000;       // RANSAC hypotheses per plane (adaptive, 99 % confidence)
  double confidence = 0.99;
  std::uint32_t seed = 1;      // fixed: results are reproducible
};

struct RansacLseResult {
  PlaneSegments planes;        // PlaneSegment::points = inliers x sample_step^2 (pixels covered)
  double squared_error = 0.0;  // truncated squared error of the winning segmentation (m^2)
  int winning_iteration = 0;
};

// Throws ParameterError for options out of range. `planes.labels` marks the sampled pixels only.
RansacLseResult ransac_lse_planes(const OrganizedCloud& cloud, const RansacLseOptions& options);

}  // namespace tunnelmap
