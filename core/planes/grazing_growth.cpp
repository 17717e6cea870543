#include "core/planes/grazing_growth.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/planes/plane_growing.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_slots.h"
#include "core/planes/region_grower.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

int grow_edge_on_surfaces(const OrganizedCloud& full, const GrowOptions& options, PlaneSegments& planes,
                          const std::vector<std::uint8_t>& pixel_states, RegionGrower& grower,
                          ContourBufferPool& pool) {
  const int w = full.width, h = full.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  if (n == 0 || planes.labels.size() != n || pixel_states.size() != n) return 0;
  // A seed is a 2x2 block of seed pixels: none, nothing to do (most frames of a flat scene).
  if (std::find(pixel_states.begin(), pixel_states.end(), kEdgeOnSeed) == pixel_states.end()) return 0;

  grower.reset_unlabelled(full, options, pixel_states);
  const double fxfy = full.intrinsics.fx * full.intrinsics.fy;
  std::size_t kept = planes.planes.size();
  std::int32_t next_id = static_cast<std::int32_t>(kept) + 1;
  int added = 0;
  for (int v = 0; v + 1 < h; ++v) {
    const std::uint8_t* row = pixel_states.data() + static_cast<std::size_t>(v) * w;
    // Seed pixels are sparse: jump from one to the next (memchr) instead of testing each pixel.
    for (const std::uint8_t* at = row; (at = static_cast<const std::uint8_t*>(
                                            std::memchr(at, kEdgeOnSeed, static_cast<std::size_t>(row + w - 1 - at))));
         ++at) {
      const int u = static_cast<int>(at - row);
      if (!grower.seedable(u, v)) continue;
      PlaneModel model;
      if (!grower.seed(u, v, model)) continue;
      grower.grow(u, v, next_id, model);
      if (model.count() < options.min_points) {  // too small: no statistics needed
        grower.release();
        continue;
      }
      if (kept == planes.planes.size()) add_plane_slot(planes.planes, pool);
      PlaneSegment& plane = planes.planes[kept];
      fill_segment_statistics(plane, model, options, fxfy);
      if (plane.area_m2 < options.min_area_m2) {
        grower.release();  // the slot is reused by the next region
        continue;
      }
      plane.id = next_id;
      plane.edge_on = true;
      plane.bbox_u0 = grower.bbox_u0, plane.bbox_v0 = grower.bbox_v0;
      plane.bbox_u1 = grower.bbox_u1, plane.bbox_v1 = grower.bbox_v1;
      for (const RegionGrower::Member& m : grower.members())
        planes.labels[static_cast<std::size_t>(m.v) * w + m.u] = next_id;
      ++kept, ++next_id, ++added;
    }
  }
  shrink_plane_slots(planes.planes, kept, pool);
  return added;
}

}  // namespace tunnelmap
