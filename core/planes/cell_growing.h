#pragma once
// PG&C region growing in cell order: the eq. 2 tests and the eq. 4 incremental model applied to
// square cells of pixels (cell_fits.h) instead of single pixels, then every pixel of a cell at a
// plane border (or next to one) assigned on its own to the nearest neighbouring plane within
// epsilon. Two passes over the pixels and no per-pixel normals: the growing itself runs on a
// few thousand cells.
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/border_assignment.h"
#include "core/planes/cell_fits.h"
#include "core/planes/grow_options.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_segment.h"
#include "core/planes/plane_slots.h"

namespace tunnelmap {

// Buffers reused from frame to frame (no allocation per frame in the steady state).
struct CellGrowingScratch {
  CellGrid grid;
  std::vector<std::int32_t> cell_labels;  // per cell: 0 free, else the region's id
  std::vector<std::uint8_t> seeded;       // per cell: tried as a seed or part of a dropped region
  std::vector<double> cos_angle;         // per cell: the eq. 2 angle test's bound (lambda + its normal's error)
  std::vector<std::int32_t> queue;        // the growing region's cells
  std::vector<std::int32_t> seeds;        // planar cells, flattest first
  std::vector<std::int32_t> bucket_start;
  std::vector<PixelTally> tallies;         // per kept plane: interior cells + assigned border pixels
  std::vector<Eigen::Vector4f> assign_planes;  // per kept plane: n (unit), d of its cell model
  PlaneModel noisy_cells;                  // the growing region's noisy cells (cell_growing.cpp)
};

// Planes (statistics, labels, bounding boxes; no contours) of
// `cloud` with cells of options.cell_px pixels. Points only: cloud.normals is not read.
void extract_planes_by_cells(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out,
                             CellGrowingScratch& scratch, ContourBufferPool& pool);

}  // namespace tunnelmap
