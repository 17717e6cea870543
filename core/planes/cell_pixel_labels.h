#pragma once
// The pixel labels of the cell order (cell_growing.h) once its cells are grown: a labelled cell
// with no other plane beside it takes all its valid pixels; in any other cell next to a plane each
// pixel joins the nearest candidate plane within epsilon (border_assignment.h), and each plane's
// tally adds up what it took.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/border_assignment.h"
#include "core/planes/cell_fits.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

// Writes out.labels (resized to the cloud) from `cell_labels` (per cell: 0 or a plane id) and
// adds to tallies[id - 1]. `planes[id - 1]` is plane id's (n, d) with unit n; `eps` is eq. 2's
// distance bound.
void assign_cell_pixels(const OrganizedCloud& cloud, const CellGrid& grid, double eps,
                        const std::vector<std::int32_t>& cell_labels, const std::vector<Eigen::Vector4f>& planes,
                        std::vector<PixelTally>& tallies, PlaneSegments& out);

}  // namespace tunnelmap
