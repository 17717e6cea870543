#pragma once
// The fine pass of coarse-to-fine PG&C for surfaces seen edge-on. On the growing grid,
// neighbouring samples of a surface at incidence angle theta lie about
//   step * r / (f cos theta)
// apart (r: range, f: focal length in pixels). Beyond the candidate distance the grid cannot
// connect them, so a narrow surface seen nearly edge-on (a wall's edge band looking down the
// tunnel) breaks into fragments below the minimum size, although every-pixel growing, with
// step times closer neighbours, would find it. This pass runs the paper's every-pixel growing,
// seeded only at such pixels and joining only pixels no plane took.
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct GrowOptions;

// True where the growing grid of `step` cannot connect a surface through (p, n): its grid
// neighbours in the steepest direction lie beyond `candidate_distance_m`.
inline bool grid_cannot_connect(const Eigen::Vector3f& p, const Eigen::Vector3f& n, int step, float focal_px,
                                float candidate_distance_m) {
  // step r / (f cos theta) > c  with  cos theta = |n.p| / r   <=>   step r^2 > c f |n.p|
  return static_cast<float>(step) * p.squaredNorm() > candidate_distance_m * focal_px * std::abs(n.dot(p));
}

// Every-pixel growing from the unlabelled pixels where grid_cannot_connect holds; `planes`
// holds full-resolution labels and statistics and `models` their eq. 3-4 sums by id (after
// refine_to_full_resolution). A grown region that touches a plane and passes the eq. 2 tests
// as a whole against it (its mean normal within lambda of the plane's, its mean point within
// epsilon / 2 of the plane) is the same surface, cut off from its grid samples: it joins that
// plane, whatever its size. Any other region of at least the minimum size becomes a new plane
// with the next id. Statistics, bounding boxes, labels and models are kept up to date;
// contours are left to the caller. Returns the number of planes added.
int grow_edge_on_surfaces(const OrganizedCloud& full, int step, const GrowOptions& options, PlaneSegments& planes,
                          std::vector<PlaneModel>& models);

}  // namespace tunnelmap
