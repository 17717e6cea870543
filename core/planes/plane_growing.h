#pragma once
// Stage 3: PG&C plane extraction by region growing (paper section 2.1).
#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct GrowOptions {
  double angle_deg = 4.0;               // lambda, eq. 2
  double distance_m = 0.015;            // epsilon, eq. 2
  double candidate_distance_m = 0.040;  // point to candidate point
  int neighbourhood_n = 5;              // n*n-1 candidates
  int min_points = 40;
  double min_area_m2 = 0.004;
  bool refit_normal = true;             // report the least-squares normal of the grown points
  int grid_step = 2;                    // grow on every k-th pixel, then assign the rest (1 = every pixel, the paper)
  bool edge_on_pass = true;             // grid step > 1: every-pixel growing where the grid cannot connect
  bool compute_contours = true;
};

PlaneSegments extract_planes(const OrganizedCloud& cloud, const GrowOptions& options);
// The same into `out`, reusing its buffers (no allocation per frame in the steady state).
void extract_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out);

}  // namespace tunnelmap
