#include "core/planes/plane_contour.h"

#include <algorithm>
#include <cmath>

#include "core/planes/boundary_trace.h"
#include "core/planes/polygon_simplify.h"

namespace tunnelmap {

void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, double tolerance_px) {
  ContourScratch scratch;
  compute_contour(labels, width, K, plane, scratch, tolerance_px);
}

void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, ContourScratch& scratch, double tolerance_px) {
  plane.contour.clear();  // keeps its capacity: the caller reuses the plane slot frame after frame
  if (width <= 0) return;
  // The label image's own bounds clip the box (defensive: the grower's boxes lie inside it).
  const int height = static_cast<int>(labels.size() / static_cast<std::size_t>(width));
  const int u0 = std::max(plane.bbox_u0, 0), v0 = std::max(plane.bbox_v0, 0);
  const int u1 = std::min(plane.bbox_u1, width - 1), v1 = std::min(plane.bbox_v1, height - 1);
  if (u0 > u1 || v0 > v1) return;
  // The scratch's buffers only grow: no allocation per plane in the steady state.
  std::vector<PixelPoint>& outline = scratch.outline;
  std::vector<PixelPoint>& polygon = scratch.polygon;
  trace_largest_outer_boundary(labels.data(), width, plane.id, u0, v0, u1, v1, outline, scratch.trace);
  simplify_closed_polygon(outline, tolerance_px, polygon, scratch.simplify);
  plane.contour.reserve(polygon.size());  // at most one allocation, only if the slot is too small
  for (const PixelPoint& pt : polygon) {
    const Eigen::Vector3d ray = K.ray(pt.x, pt.y);
    const double denom = plane.normal.dot(ray);
    if (std::abs(denom) < 1e-9) continue;  // ray parallel to the plane
    const double t = -plane.offset_m / denom;
    if (t > 0) plane.contour.push_back(ray * t);
  }
}

}  // namespace tunnelmap
