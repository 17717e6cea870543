#pragma once
// The buffers of the plane stage (extract_planes), owned by the caller: one PlaneScratch per
// caller that extracts concurrently (Pipeline keeps one in each FrameResult, SequenceRunner one
// per worker). Everything only grows, so frame after frame allocates nothing in the steady state
// (tests/allocation).
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/cell_growing.h"
#include "core/planes/plane_contour.h"
#include "core/planes/plane_refinement.h"
#include "core/planes/plane_slots.h"
#include "core/planes/region_grower.h"
#include "core/planes/residual_growth.h"

namespace tunnelmap {

struct PlaneScratch {
  RegionGrower grower;          // the growing on the grid (every pixel when grid_step is 1)
  RegionGrower edge_on_grower;  // the edge-on pass at full resolution: its own size, no re-sizing
  OrganizedCloud coarse;        // the growing grid's samples
  std::vector<std::int32_t> coarse_labels;
  std::vector<std::uint8_t> edge_on_states;
  RefinementScratch refinement;
  CellGrowingScratch cells;     // the cell-based growing order (grow.cell_px > 0)
  ResidualGrowthScratch residual;  // its pass over the pixels no cell plane took
  ContourScratch contour;
  ContourBufferPool contour_pool;  // contour buffers of removed plane slots, for the next new ones
};

}  // namespace tunnelmap
