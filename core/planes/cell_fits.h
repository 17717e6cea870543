#pragma once
// Square cells of an organised cloud, each with its point moments and least-squares plane,
// from one pass over the points: the units the cell-based growing order joins (the eq. 2 tests
// and the eq. 4 model applied to a cell's points at once). Moments are taken about a point of
// the cell itself, in float, so they keep millimetre detail at any range.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"

namespace tunnelmap {

struct CellFit {
  int count = 0;                                      // valid points
  Eigen::Vector3d sum_p = Eigen::Vector3d::Zero();    // sum of points
  double sum_pp[6] = {0, 0, 0, 0, 0, 0};              // sum p p^T about the origin: xx xy xz yy yz zz
  double sum_z3 = 0.0;                                // sum z^3 (pixel footprints, segment_statistics)
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double scatter[6] = {0, 0, 0, 0, 0, 0};             // sum (p - mean)(p - mean)^T
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();   // unit, facing the camera; zero if not planar
  double mse = 0.0;                                   // mean squared distance to its own plane
  double normal_se = 0.0;  // standard error of the normal's direction (radians), from the fit's residual
  bool fitted = false;     // enough valid points for a plane: normal and mse are set
  bool quiet = false;      // within the fixed RMS bound (compute_cell_fits' max_rms_m)
  double max_mse = 0.0;    // the planarity bound on mse: the fixed one or the noise bound at this range
  bool planar = false;     // quiet, or within the noise bound with a block normal (smooth_cell_normals)
  // The normal of the planar cells of the 3x3 block around this one when they fit one plane
  // (block_fitted, see smooth_cell_normals), else this cell's own; and its standard error.
  Eigen::Vector3d block_normal = Eigen::Vector3d::Zero();
  double block_se = 0.0;
  bool block_fitted = false;

  // Mean squared distance of the cell's points to the plane n.x + d = 0 (exact, from moments).
  double mse_to(const Eigen::Vector3d& n, double d) const {
    const double spread = n.x() * (n.x() * scatter[0] + 2 * n.y() * scatter[1] + 2 * n.z() * scatter[2]) +
                          n.y() * (n.y() * scatter[3] + 2 * n.z() * scatter[4]) + n.z() * n.z() * scatter[5];
    const double off = n.dot(mean) + d;
    return spread / count + off * off;
  }
};

// A cell the noise along the rays makes planar (facing_cells.h): its block's normal and
// standard error, and its planarity bound at that facing.
struct CellAdmission {
  int cell = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double se = 0.0, max_mse = 0.0;
};

struct CellGrid {
  int cell_px = 0;  // side of a cell; cells on the right and bottom edge may be smaller
  int cols = 0, rows = 0;
  std::vector<CellFit> cells;  // rows * cols, row-major
  // Buffers kept to avoid allocating per frame: compute_cell_fits' per-quantity arrays over the
  // cells (cell_fit_kernels.h) and ratios, smooth_cell_normals' values and sums.
  std::vector<double> fit_arrays, ratios;
  std::vector<double> row_sums, block_sums;
  std::vector<char> candidates;          // admit_cells_facing_the_camera's
  std::vector<CellAdmission> admissions;  // admit_cells_facing_the_camera's
  double noise_per_m2 = 0.0;     // the frame's depth noise, sigma / z^2 (1/m); 0 when not estimated
  double axial_noise_per_m2 = 0.0;  // the same along the rays (facing_cells.h); 0 when not estimated
  double noise_multiple = 0.0;      // compute_cell_fits' noise_multiple

  int index(int cu, int cv) const { return cv * cols + cu; }
};

// A cell is fitted when at least `min_valid` of its pixels have a point. It is quiet when the
// RMS distance to its least-squares plane is at most `max_rms_m`, and planar when that RMS is
// at most the larger of `max_rms_m` and `noise_multiple` times the frame's depth noise at its
// range (sigma = c z^2, c estimated from the cells; 0 = no noise bound): far away a flat
// surface's noise alone exceeds any fixed bound. It also estimates the noise along the rays
// (axial_noise_per_m2, facing_cells.h).
void compute_cell_fits(const OrganizedCloud& cloud, int cell_px, int min_valid, double max_rms_m,
                       CellGrid& grid, double noise_multiple = 0.0);

// The square root of the lower quartile of `squares` (reordered), 0 with fewer than 16: a
// noise estimate that flat surfaces set and edges and clutter only raise the upper quantiles of.
double root_of_lower_quartile(std::vector<double>& squares);

// Each planar cell's block normal: the least-squares normal of the planar cells among it and
// its 8 neighbours, when their points lie within the members' planarity bounds of it (mean
// squared distance); else its own normal. A planar cell that is not quiet and has no block
// normal stops being planar. Then the cells of surfaces facing the camera whose noise only
// the noise along the rays explains become planar (admit_cells_facing_the_camera).
// Nine cells' points pin the direction down about nine times better than one cell's (three
// times the points over three times the extent), as a wider window does for pixel normals.
void smooth_cell_normals(CellGrid& grid);

// Moments about `ref` of the valid points in pixels [u0, u1) x [v0, v1): count, sums of d (3),
// of d d^T (xx xy xz yy yz zz) and of dz^3, d = p - ref; float sums, so `ref` must lie near
// the points.
void cell_moments(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, const Eigen::Vector3f& ref,
                  double m[11]);

// Smallest-eigenvalue eigenvector of a symmetric 3x3 matrix given as xx xy xz yy yz zz, by two
// steps of inverse iteration through the adjugate (exact for a rank-2 matrix, far cheaper than
// a full eigen-solver). Returns false for a matrix of rank below 2 (no unique normal).
bool smallest_eigenvector(const double m[6], Eigen::Vector3d& v);

}  // namespace tunnelmap
