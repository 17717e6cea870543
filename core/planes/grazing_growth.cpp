#include "core/planes/grazing_growth.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/planes/plane_growing.h"
#include "core/planes/plane_slots.h"
#include "core/planes/region_grower.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

namespace {

// The plane among those 8-adjacent to the region's pixels that the region passes the eq. 2
// tests against as a whole (closest mean point wins), or 0.
std::int32_t plane_to_join(const std::vector<RegionGrower::Member>& members, const std::vector<std::int32_t>& labels,
                           int w, int h, const std::vector<PlaneModel>& models, const PlaneModel& region,
                           float eps, float cos_angle) {
  std::int32_t touched[8];
  int n_touched = 0;
  for (const RegionGrower::Member& m : members) {
    for (int dv = -1; dv <= 1; ++dv) {
      const int v = m.v + dv;
      if (v < 0 || v >= h) continue;
      for (int du = -1; du <= 1; ++du) {
        const int u = m.u + du;
        if (u < 0 || u >= w) continue;
        const std::int32_t l = labels[static_cast<std::size_t>(v) * w + u];
        if (l == 0 || std::find(touched, touched + n_touched, l) != touched + n_touched) continue;
        if (n_touched < 8) touched[n_touched++] = l;
      }
    }
  }
  const Eigen::Vector3d c = region.mean_point();
  const Eigen::Vector3d nr = region.sum_normal().normalized();
  std::int32_t best = 0;
  double best_dist = eps;
  for (int k = 0; k < n_touched; ++k) {
    const PlaneModel& p = models[touched[k]];
    const Eigen::Vector3d np = p.sum_normal().normalized();
    if (np.dot(nr) < cos_angle) continue;
    const double dist = std::abs(np.dot(c - p.mean_point()));
    if (dist <= best_dist) best_dist = dist, best = touched[k];
  }
  return best;
}

void grow_bbox(PlaneSegment& plane, const RegionGrower& g) {
  plane.bbox_u0 = std::min(plane.bbox_u0, g.bbox_u0), plane.bbox_v0 = std::min(plane.bbox_v0, g.bbox_v0);
  plane.bbox_u1 = std::max(plane.bbox_u1, g.bbox_u1), plane.bbox_v1 = std::max(plane.bbox_v1, g.bbox_v1);
}

}  // namespace

int grow_edge_on_surfaces(const OrganizedCloud& full, int step, const GrowOptions& options, PlaneSegments& planes,
                          std::vector<PlaneModel>& models) {
  const int w = full.width, h = full.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  if (step <= 1 || n == 0 || planes.labels.size() != n || models.size() != planes.planes.size() + 1) return 0;
  const float focal = static_cast<float>(0.5 * (full.intrinsics.fx + full.intrinsics.fy));
  const float cand = static_cast<float>(options.candidate_distance_m);
  const float eps = static_cast<float>(options.distance_m);
  const float cos_angle = static_cast<float>(std::cos(options.angle_deg * M_PI / 180.0));

  // Seeds: unlabelled pixels with a normal where the grid could not connect the surface.
  thread_local std::vector<std::uint8_t> may_seed;
  may_seed.resize(n);
  std::size_t seeds = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& nr = full.normals[i];
    const bool s = planes.labels[i] == 0 && nr.x() == nr.x() &&
                   grid_cannot_connect(full.points[i], nr, step, focal, cand);
    may_seed[i] = s;
    seeds += s;
  }
  if (seeds < 4) return 0;  // a seed is a 2x2 block

  thread_local RegionGrower grower;
  grower.reset_unlabelled(full, options, planes.labels, may_seed);
  const double fxfy = full.intrinsics.fx * full.intrinsics.fy;
  // The region being grown takes a provisional id past every plane's; only planes' ids reach
  // planes.labels, so a region never "touches" itself.
  const std::int32_t region_id = std::numeric_limits<std::int32_t>::max();
  std::size_t kept = planes.planes.size();
  int added = 0;
  for (int v = 0; v + 1 < h; ++v) {
    const std::uint8_t* row = may_seed.data() + static_cast<std::size_t>(v) * w;
    for (int u = 0; u + 1 < w; ++u) {
      if (!row[u] || !grower.seedable(u, v)) continue;
      PlaneModel model;
      if (!grower.seed(u, v, model)) continue;
      grower.grow(u, v, region_id, model);
      std::int32_t id = plane_to_join(grower.members(), planes.labels, w, h, models, model, eps, cos_angle);
      if (id) {
        PlaneSegment& plane = planes.planes[static_cast<std::size_t>(id) - 1];
        models[id].merge(model);
        fill_segment_statistics(plane, models[id], options, fxfy);
        grow_bbox(plane, grower);
      } else {
        if (kept == planes.planes.size()) add_plane_slot(planes.planes);
        PlaneSegment& plane = planes.planes[kept];
        fill_segment_statistics(plane, model, options, fxfy);
        if (plane.points < options.min_points || plane.area_m2 < options.min_area_m2) {
          grower.release();  // the slot is reused by the next region
          continue;
        }
        id = static_cast<std::int32_t>(kept) + 1;
        plane.id = id;
        plane.bbox_u0 = grower.bbox_u0, plane.bbox_v0 = grower.bbox_v0;
        plane.bbox_u1 = grower.bbox_u1, plane.bbox_v1 = grower.bbox_v1;
        models.push_back(model);
        ++kept, ++added;
      }
      for (const RegionGrower::Member& m : grower.members())
        planes.labels[static_cast<std::size_t>(m.v) * w + m.u] = id;
    }
  }
  shrink_plane_slots(planes.planes, kept);
  return added;
}

}  // namespace tunnelmap
