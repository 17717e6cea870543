#pragma once
// Reusing PlaneSegments::planes from frame to frame without heap allocations: the vector's own
// capacity persists, but a slot destroyed by shrinking takes its contour buffer with it. These
// park such buffers in a pool kept with the scratch of the stage (PlaneScratch) and hand them to
// the next new slot.
#include <utility>
#include <vector>

#include "core/planes/plane_segment.h"

namespace tunnelmap {

// Contour buffers of removed plane slots, waiting for the next new slot.
struct ContourBufferPool {
  std::vector<std::vector<Eigen::Vector3d>> spare;
};

// Appends a slot, with a recycled contour buffer when one is parked.
inline PlaneSegment& add_plane_slot(std::vector<PlaneSegment>& planes, ContourBufferPool& pool) {
  planes.emplace_back();
  if (!pool.spare.empty()) {
    planes.back().contour = std::move(pool.spare.back());
    planes.back().contour.clear();
    pool.spare.pop_back();
  }
  // Room for a long simplified outline (VGA frames: up to ~100 vertices), so that slots trading
  // planes from frame to frame rarely need to grow; 3 kB per slot.
  if (planes.back().contour.capacity() < 128) planes.back().contour.reserve(128);
  return planes.back();
}

// Shrinks to `n` slots, parking the contour buffers of the removed ones.
inline void shrink_plane_slots(std::vector<PlaneSegment>& planes, std::size_t n, ContourBufferPool& pool) {
  for (std::size_t i = n; i < planes.size(); ++i)
    if (planes[i].contour.capacity() > 0) pool.spare.push_back(std::move(planes[i].contour));
  if (n < planes.size()) planes.resize(n);
}

}  // namespace tunnelmap
