#include "core/mapping/plate_rims.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap {

namespace {

// Whether plate pixel (u, v) of plane `label` lies on an opening's rim: a neighbour is not the
// plate, and the first valid point past the edge in that direction is farther along its ray by
// `see_through_m` (a wall meeting the plate at a corner is at about the same range).
bool on_rim(const FrameResult& r, int u, int v, int label, const FrameWallsOptions& o) {
  const PlaneSegments& ps = r.planes;
  const int W = ps.width, H = ps.height;
  const Eigen::Vector3f& p = r.cloud.points[static_cast<std::size_t>(v) * W + u];
  const float range = p.norm();
  static constexpr int kDu[4] = {1, -1, 0, 0}, kDv[4] = {0, 0, 1, -1};
  for (int d = 0; d < 4; ++d) {
    const int u1 = u + kDu[d], v1 = v + kDv[d];
    if (u1 < 0 || v1 < 0 || u1 >= W || v1 >= H) continue;
    if (ps.labels[static_cast<std::size_t>(v1) * W + u1] == label) continue;
    for (int k = 1; k <= o.rim_search_px; ++k) {
      const int uk = u + k * kDu[d], vk = v + k * kDv[d];
      if (uk < 0 || vk < 0 || uk >= W || vk >= H) break;
      const Eigen::Vector3f& q = r.cloud.points[static_cast<std::size_t>(vk) * W + uk];
      if (!OrganizedCloud::valid(q)) continue;
      if (q.norm() > range + o.see_through_m) return true;
      break;
    }
  }
  return false;
}

}  // namespace

void extract_plate_rims(const FrameResult& r, const std::vector<int>& plate_ids,
                        const FrameWallsOptions& o, std::vector<RimPoint>& out) {
  const PlaneSegments& ps = r.planes;
  for (const int id : plate_ids) {
    const auto plane = std::find_if(ps.planes.begin(), ps.planes.end(),
                                    [&](const PlaneSegment& s) { return s.id == id; });
    if (plane == ps.planes.end()) continue;
    const Eigen::Vector3f n = plane->normal.cast<float>();
    const float offset = static_cast<float>(plane->offset_m);
    const std::size_t first = out.size();
    for (int v = plane->bbox_v0; v <= plane->bbox_v1; ++v)
      for (int u = plane->bbox_u0; u <= plane->bbox_u1; ++u) {
        const std::size_t i = static_cast<std::size_t>(v) * ps.width + u;
        if (ps.labels[i] != id || !OrganizedCloud::valid(r.cloud.points[i])) continue;
        if (!on_rim(r, u, v, id, o)) continue;
        // Along the pixel's ray onto the plate: the depth noise of one pixel moves it along the
        // ray, which the fitted plane averages out.
        const Eigen::Vector3f& p = r.cloud.points[i];
        const float along = n.dot(p);
        if (std::abs(along) < 1e-6f) continue;
        out.push_back({p * (-offset / along), id});
      }
    // Thin out evenly along the scan order (rows), which spreads the kept points over the rim.
    const std::size_t found = out.size() - first;
    const std::size_t keep = static_cast<std::size_t>(std::max(1, o.max_rim_points_per_plate));
    if (found <= keep) continue;
    for (std::size_t k = 0; k < keep; ++k) out[first + k] = out[first + k * found / keep];
    out.resize(first + keep);
  }
}

}  // namespace tunnelmap
