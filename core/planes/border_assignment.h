#pragma once
// The per-pixel half of the cell-based growing order: in a cell at a plane border, each valid
// pixel joins the nearest neighbouring plane within epsilon (eq. 2's distance test), or none.
// One SSE pass per cell writes the labels and tallies what each plane gained.
#include <Eigen/Core>
#include <cstdint>

#include "core/frame/organized_cloud.h"

namespace tunnelmap {

// What a plane's assigned pixels add up to: enough for its point count, centroid, area
// (segment_statistics) and bounding box. The plane itself stays the fit of its grown cells.
struct PixelTally {
  long count = 0;
  Eigen::Vector3d sum_p = Eigen::Vector3d::Zero();
  double sum_z3 = 0.0;
  int u0 = 0, v0 = 0, u1 = -1, v1 = -1;  // bounding box, inclusive; empty while u1 < u0

  void include_box(int bu0, int bv0, int bu1, int bv1);
};

// Labels each valid pixel of [u0, u1) x [v0, v1) (at most 32 pixels wide) with the nearest of
// the `ncand` (<= 9) candidate planes within `eps`, or 0, and adds it to that plane's tally.
// `planes[id - 1]` is plane id's (n, d) with unit n; `tallies[id - 1]` its tally.
void assign_to_nearest_plane(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1,
                             const Eigen::Vector4f* planes, const std::int32_t* cand, int ncand, float eps,
                             std::int32_t* labels, PixelTally* tallies);

}  // namespace tunnelmap
