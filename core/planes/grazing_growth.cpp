
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

// A fragment of a plane's own surface has its mean point on that plane up to averaged noise
// (about a millimetre); a neighbouring plate offset by a few millimetres (a middle plate and
// its edge band) is another surface. Joining within the full epsilon merged edge bands into
// their middle plates (lab recall 95.2 %); half of it keeps them apart (96.3 %) and still joins
// enough fragments to report fewer planes than every-pixel growing (240 simulated frames).
constexpr double kJoinDistanceFraction = 0.5;

// The plane among those adjacent to the grown region that the region passes the eq. 2 tests
// against as a whole (closest mean point wins), or 0; the distance test uses
// kJoinDistanceFraction of epsilon.
std::int32_t plane_to_join(const RegionGrower& grower, const std::vector<PlaneModel>& models,
                           const PlaneModel& region, float eps, float cos_angle) {
  std::int32_t touched[8];
  const int n_touched = grower.adjacent_planes(touched, 8);
  const Eigen::Vector3d c = region.mean_point();
  const Eigen::Vector3d nr = region.sum_normal().normalized();
  std::int32_t best = 0;
  double best_dist = kJoinDistanceFraction * eps;
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
  // The region being grown takes a provisional id past every plane's (never a plane's id).
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
      std::int32_t id = plane_to_join(grower, models, model, eps, cos_angle);
      if (id) {
        PlaneSegment& plane = planes.planes[static_cast<std::size_t>(id) - 1];
        models[id].merge(model);
        fill_segment_statistics(plane, models[id], options, fxfy);
        grow_bbox(plane, grower);
      } else {
        if (model.count() < options.min_points) {  // too small on its own: no statistics needed
          grower.release();
          continue;
        }
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
      grower.mark_members(id);
      for (const RegionGrower::Member& m : grower.members())
        planes.labels[static_cast<std::size_t>(m.v) * w + m.u] = id;
    }
  }
  shrink_plane_slots(planes.planes, kept);
  return added;
}

}  // namespace tunnelmap
