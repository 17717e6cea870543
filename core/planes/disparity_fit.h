#pragma once
// A plane fitted where depth noise does not bias it: in disparity space, where a plane seen
// through a pinhole is linear, 1/z = a x' + b y' + c over the normalised image coordinates
// x' = x/z, y' = y/z. Depth noise moves a point along its ray; it changes 1/z only and leaves
// x', y' exact, so ordinary least squares there is unbiased. A least-squares fit to the points
// themselves is not (errors in variables): at grazing incidence the rays lie nearly in the
// plane, and the noise along them tilts a small fragment's normal by degrees. With the
// structured-light noise sigma_z ~ z^2 the noise of 1/z is the same at every range, so equal
// weights are the right ones too.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/cell_fits.h"

namespace tunnelmap {

// Sums over a cell's valid pixels about its corner (u0, v0): du = u - u0, dv = v - v0, w = 1/z.
enum DisparitySum : int { kSumU, kSumV, kSumUU, kSumUV, kSumVV, kSumW, kSumUW, kSumVW, kDisparitySums };

// Sums over points for the disparity-space fit, in normalised image coordinates.
struct DisparityMoments {
  double n = 0, x = 0, y = 0, w = 0, xx = 0, xy = 0, yy = 0, xw = 0, yw = 0;

  // Adds a cell's `count` pixels with corner (u0, v0) and sums `s` (DisparitySum).
  void add_cell(const double s[kDisparitySums], double count, int u0, int v0, const Intrinsics& k);
  // The plane n.p + d = 0 (n unit, facing the camera: d > 0); false when the points do not
  // span two directions of the image (a line of pixels) or the plane passes through the camera.
  bool plane(Eigen::Vector3d& normal, double& d) const;
};

// Adds the valid points of the given cells of `grid` (cells of grid.cell_px pixels).
// One pass over their pixels: done only for the regions that need it, it cost 0.2-0.35 ms on
// the real frames; as sums in the cell kernel for every cell, 0.2 ms (the kernel's registers
// spill).
void add_cell_points(const OrganizedCloud& cloud, const CellGrid& grid, const std::vector<std::int32_t>& cells,
                     DisparityMoments& m);

}  // namespace tunnelmap
