#pragma once
// How far the cell order's normals lie from the true surfaces' next to the standard errors it
// claims for them, by range (tunnelmap_plane_recall --normal-errors). The angle test widens
// lambda by twice a cell's claimed error (core/planes/cell_growing.cpp), so an error claimed too
// small splits a flat surface and one claimed too large merges steps: this is the measurement
// that shows which.
#include <cstdint>
#include <string>
#include <vector>

#include "core/evaluation/segmentation_metrics.h"
#include "core/planes/cell_fits.h"

namespace tunnelmap::recall {

// Range bands of the report: 0-1, 1-2, 2-3, 3-4 and beyond 4 m.
constexpr int kRangeBands = 5;

struct NormalErrors {
  std::string preset;
  // Per range band, over the cells with a block normal whose 3x3 block of pixels lies on one
  // true surface: the block normal's angle to that surface's (degrees), and that angle over the
  // block normal's standard error.
  std::vector<double> error_deg[kRangeBands], error_over_se[kRangeBands];

  // One frame: its cells, the true surface of each pixel and the surfaces' fitted normals
  // (`details` of score_segmentation with the cloud).
  void add_frame(const CellGrid& grid, int width, int height, const std::vector<std::uint16_t>& truth,
                 const std::vector<SurfaceDetail>& details);
};

// A markdown table, one row per preset and range band.
std::string normal_error_report(const std::vector<NormalErrors>& runs);

// The largest median error / standard error over the range bands of at least `min_cells` cells,
// with the band that has it ("field, step 2, 0-1 m").
double worst_median_error_ratio(const std::vector<NormalErrors>& runs, std::size_t min_cells, std::string& where);

}  // namespace tunnelmap::recall
