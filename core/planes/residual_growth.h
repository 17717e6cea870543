#pragma once
// The cell order's pass for surfaces narrower than a cell. Seen nearly edge-on, a wall's edge
// band down the tunnel is a sliver a few pixels wide: every cell it crosses also holds the wall
// or the floor, fits no plane, and the band stays unlabelled (on the simulated lab frames, over
// 90 % of such a band's pixels). This pass grows single pixels among the pixels no plane took:
// seeded in unlabelled cells where a 5x5 window of them fits a plane within epsilon/2 seen at
// 75 degrees of incidence or more, that the cells cannot hold (grid_cannot_connect at half a
// cell); joined by eq. 2's distance test to the region's least-squares plane and the candidate
// distance to the pixel it is reached from (the 8 neighbours, and the pixel beyond one without
// a point: such slivers have dropouts). The cell order has no per-pixel normals: the seed
// window's fit stands in for eq. 2's normal test, and a region whose plane turns out to face
// the camera (under 70 degrees of incidence) is dropped.
#include <cstdint>
#include <utility>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/cell_fits.h"
#include "core/planes/grow_options.h"
#include "core/planes/plane_segment.h"
#include "core/planes/plane_slots.h"

namespace tunnelmap {

// Buffers reused from frame to frame (no allocation per frame in the steady state).
struct ResidualGrowthScratch {
  std::vector<std::int32_t> queue;    // the growing region's pixels
  std::vector<std::int32_t> touched;  // pixels marked in the label image, cleared at the end
  std::vector<std::pair<std::int32_t, std::int32_t>> rejected;  // the region's rejected pixels, old marks
};

// Adds the planes found among the unlabelled pixels of `out` after the cell order grew the
// cells of `grid` into the regions `cell_labels` (0 = none): next ids, full-resolution
// statistics, labels and bounding boxes, marked edge_on; no contours. Seeds only in unlabelled
// cells, where the frame's depth noise (sigma = grid.noise_per_m2 z^2) is within epsilon / 2
// and 4 mm. Returns the number of planes added.
int grow_residual_slivers(const OrganizedCloud& cloud, const GrowOptions& options, const CellGrid& grid,
                          const std::vector<std::int32_t>& cell_labels, PlaneSegments& out,
                          ResidualGrowthScratch& scratch, ContourBufferPool& pool);

}  // namespace tunnelmap
