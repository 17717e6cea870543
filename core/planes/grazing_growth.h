#pragma once
// The fine pass of coarse-to-fine PG&C for surfaces seen edge-on. On the growing grid,
// neighbouring samples of a surface at incidence angle theta lie about
//   step * r / (f cos theta)
// apart (r: range, f: focal length in pixels). Beyond the candidate distance the grid cannot
// connect them, so a narrow surface seen nearly edge-on (a wall's edge band looking down the
// tunnel) breaks into fragments below the minimum size, although every-pixel growing, with
// step times closer neighbours, would find it. This pass runs the paper's every-pixel growing,
// seeded only at such pixels and joining only pixels no plane took.
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct GrowOptions;
class RegionGrower;
struct ContourBufferPool;

// True where the growing grid of `step` cannot connect a surface through (p, n): its grid
// neighbours in the steepest direction lie beyond `candidate_distance_m`.
inline bool grid_cannot_connect(const Eigen::Vector3f& p, const Eigen::Vector3f& n, int step, float focal_px,
                                float candidate_distance_m) {
  // step r / (f cos theta) > c  with  cos theta = |n.p| / r   <=>   step r^2 > c f |n.p|
  return static_cast<float>(step) * p.squaredNorm() > candidate_distance_m * focal_px * std::abs(n.dot(p));
}

// Each pixel's part in the pass: taken (by a plane, or without a normal), joinable (free), or
// a seed (free, and grid_cannot_connect holds). Classified by refine_to_full_resolution.
constexpr std::uint8_t kEdgeOnTaken = 0, kEdgeOnJoinable = 1, kEdgeOnSeed = 2;

// Every-pixel growing (the paper's PG&C at full resolution), seeded only at kEdgeOnSeed pixels
// and joining only free pixels, after refine_to_full_resolution: each region of at least the
// minimum size becomes a plane with the next id, full-resolution statistics, bounding box and
// labels, marked edge_on; contours are left to the caller. The regions are not merged into
// the grid's planes: merging moved zone offsets (field height sigma 0.15 -> 1.2 mm), and the
// tunnel stage measures no zone from edge-on planes. Returns the number of planes added.
// `grower` and `pool` are the caller's reused buffers (PlaneScratch): no allocation per frame.
int grow_edge_on_surfaces(const OrganizedCloud& full, const GrowOptions& options, PlaneSegments& planes,
                          const std::vector<std::uint8_t>& pixel_states, RegionGrower& grower,
                          ContourBufferPool& pool);

}  // namespace tunnelmap
