#include "core/mapping/plate_rims.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tunnelmap {

namespace {

// The opening's edge next to plate pixel (u, v) of plane `label`, if there is one: a neighbour is
// not the plate's, and walking on in that direction the pixels stay on the plate's plane (the
// plate's last pixels, left unlabelled at a depth edge) until the first one that lies at least
// `see_through_m` farther along its ray (a wall meeting the plate at a corner is at about the
// same range). The edge lies between the plate's last pixel and that one: the ray half-way
// between them, met with the plate's plane.
std::optional<Eigen::Vector3f> rim_point(const FrameResult& r, const PlaneSegment& plane, int u, int v,
                                         const FrameWallsOptions& o) {
  const PlaneSegments& ps = r.planes;
  const int W = ps.width, H = ps.height;
  const auto at = [&](int x, int y) -> const Eigen::Vector3f& { return r.cloud.points[static_cast<std::size_t>(y) * W + x]; };
  const Eigen::Vector3f n = plane.normal.cast<float>();
  const float offset = static_cast<float>(plane.offset_m);
  static constexpr int kDu[4] = {1, -1, 0, 0}, kDv[4] = {0, 0, 1, -1};
  for (int d = 0; d < 4; ++d) {
    const int u1 = u + kDu[d], v1 = v + kDv[d];
    if (u1 < 0 || v1 < 0 || u1 >= W || v1 >= H) continue;
    if (ps.labels[static_cast<std::size_t>(v1) * W + u1] == plane.id) continue;
    Eigen::Vector3f last = at(u, v);
    for (int k = 1; k <= o.rim_search_px; ++k) {
      const int uk = u + k * kDu[d], vk = v + k * kDv[d];
      if (uk < 0 || vk < 0 || uk >= W || vk >= H) break;
      const Eigen::Vector3f& q = at(uk, vk);
      if (!OrganizedCloud::valid(q)) continue;
      if (std::abs(n.dot(q) + offset) < o.rim_on_plate_m) {  // still the plate
        last = q;
        continue;
      }
      if (q.norm() <= last.norm() + o.see_through_m) break;  // something else, not through
      const Eigen::Vector3f ray = last.normalized() + q.normalized();
      const float along = n.dot(ray);
      if (std::abs(along) < 1e-6f) break;
      return ray * (-offset / along);
    }
  }
  return std::nullopt;
}

}  // namespace

void extract_plate_rims(const FrameResult& r, const std::vector<int>& plate_ids,
                        const FrameWallsOptions& o, std::vector<RimPoint>& out) {
  const PlaneSegments& ps = r.planes;
  for (const int id : plate_ids) {
    const auto plane = std::find_if(ps.planes.begin(), ps.planes.end(),
                                    [&](const PlaneSegment& s) { return s.id == id; });
    if (plane == ps.planes.end()) continue;
    const std::size_t first = out.size();
    for (int v = plane->bbox_v0; v <= plane->bbox_v1; ++v)
      for (int u = plane->bbox_u0; u <= plane->bbox_u1; ++u) {
        const std::size_t i = static_cast<std::size_t>(v) * ps.width + u;
        if (ps.labels[i] != id || !OrganizedCloud::valid(r.cloud.points[i])) continue;
        const auto p = rim_point(r, *plane, u, v, o);
        if (p && p->norm() <= o.max_rim_range_m) out.push_back({*p, id});
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
