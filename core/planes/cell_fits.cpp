#include "core/planes/cell_fits.h"
#include "core/planes/facing_cells.h"

#include <Eigen/Geometry>  // cross
#include <algorithm>
#include <cmath>

#include <emmintrin.h>

#include "core/planes/cell_fit_batch.h"
#include "core/planes/cell_fit_kernels.h"
#include "core/planes/cell_moments_avx2.h"
#include "core/planes/cell_moments_tail.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {

float hsum(__m128 a) {
  const __m128 s = _mm_add_ps(a, _mm_movehl_ps(a, a));
  return _mm_cvtss_f32(_mm_add_ss(s, _mm_shuffle_ps(s, s, 1)));
}

// A valid point of the cell to take moments about: its centre pixel, else the first valid one.
bool reference_point(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, Eigen::Vector3f& ref) {
  const Eigen::Vector3f& c = cloud.points[cloud.index((u0 + u1) / 2, (v0 + v1) / 2)];
  if (OrganizedCloud::valid(c)) return ref = c, true;
  // Four pixels per step: cells without a valid centre are often wholly invalid (no return).
  for (int v = v0; v < v1; ++v) {
    const float* row = cloud.points[cloud.index(0, v)].data();
    int u = u0;
    for (; u + 4 <= u1; u += 4) {
      __m128 x, y, z;
      load_xyz4(row + 3 * u, x, y, z);
      const int ok = _mm_movemask_ps(_mm_cmpeq_ps(x, x));
      if (ok != 0) return ref = cloud.points[cloud.index(u + __builtin_ctz(ok), v)], true;
    }
    for (; u < u1; ++u) {
      const Eigen::Vector3f& p = cloud.points[cloud.index(u, v)];
      if (OrganizedCloud::valid(p)) return ref = p, true;
    }
  }
  return false;
}

}  // namespace

void cell_moments(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, const Eigen::Vector3f& ref,
                  double m[11]) {
  if (u1 - u0 >= 8 && cell_moments_avx2_available()) return cell_moments_avx2(cloud, u0, v0, u1, v1, ref, m);
  __m128 n = _mm_setzero_ps(), sx = n, sy = n, sz = n, sxx = n, sxy = n, sxz = n, syy = n, syz = n, szz = n,
         sz3 = n;
  const __m128 rx = _mm_set1_ps(ref.x()), ry = _mm_set1_ps(ref.y()), rz = _mm_set1_ps(ref.z());
  const __m128 one = _mm_set1_ps(1.0f);
  float tail[11] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  for (int v = v0; v < v1; ++v) {
    const float* row = cloud.points[cloud.index(0, v)].data();
    int u = u0;
    for (; u + 4 <= u1; u += 4) {
      __m128 x, y, z;
      load_xyz4(row + 3 * u, x, y, z);
      const __m128 ok = _mm_cmpeq_ps(z, z);  // NaN marks an invalid pixel
      const __m128 dx = _mm_and_ps(ok, _mm_sub_ps(x, rx)), dy = _mm_and_ps(ok, _mm_sub_ps(y, ry));
      const __m128 dz = _mm_and_ps(ok, _mm_sub_ps(z, rz));
      n = _mm_add_ps(n, _mm_and_ps(ok, one));
      sx = _mm_add_ps(sx, dx), sy = _mm_add_ps(sy, dy), sz = _mm_add_ps(sz, dz);
      sxx = _mm_add_ps(sxx, _mm_mul_ps(dx, dx)), sxy = _mm_add_ps(sxy, _mm_mul_ps(dx, dy));
      sxz = _mm_add_ps(sxz, _mm_mul_ps(dx, dz)), syy = _mm_add_ps(syy, _mm_mul_ps(dy, dy));
      syz = _mm_add_ps(syz, _mm_mul_ps(dy, dz));
      const __m128 dzz = _mm_mul_ps(dz, dz);
      szz = _mm_add_ps(szz, dzz), sz3 = _mm_add_ps(sz3, _mm_mul_ps(dzz, dz));
    }
    add_tail_moments(row, u, u1, ref, tail);
  }
  const __m128 all[11] = {n, sx, sy, sz, sxx, sxy, sxz, syy, syz, szz, sz3};
  for (int k = 0; k < 11; ++k) m[k] = static_cast<double>(hsum(all[k])) + tail[k];
}

namespace {

// The frame's depth noise as sigma = c z^2 (a structured-light sensor's disparity noise grows
// with the square of the range): c is the lower quartile of the fitted cells' RMS / z^2. Flat
// surfaces set it in any scene with some flat surface at some range; edges and clutter only
// raise the upper quantiles. 0 with too few fitted cells to tell.
double noise_coefficient(const CellGrid& grid, std::vector<double>& ratios) {
  ratios.clear();
  // The quartile of mse / z^4, then its root: the same cell, without a root per cell.
  for (const CellFit& c : grid.cells)
    if (c.fitted && c.mean.z() > 0) {
      const double z2 = c.mean.z() * c.mean.z();
      ratios.push_back(c.mse / (z2 * z2));
    }
  return root_of_lower_quartile(ratios);
}

}  // namespace

double root_of_lower_quartile(std::vector<double>& squares) {
  constexpr double kQuantile = 0.25;
  constexpr std::size_t kMinValues = 16;
  if (squares.size() < kMinValues) return 0.0;
  const auto q = squares.begin() + static_cast<std::ptrdiff_t>(kQuantile * static_cast<double>(squares.size() - 1));
  std::nth_element(squares.begin(), q, squares.end());
  return std::sqrt(*q);
}

bool smallest_eigenvector(const double s[6], Eigen::Vector3d& v) {
  const Eigen::Vector3d r0(s[0], s[1], s[2]), r1(s[1], s[3], s[4]), r2(s[2], s[4], s[5]);
  // Columns of the adjugate: sum over i of (product of the other two eigenvalues) e_i e_i^T,
  // dominated by the smallest eigenvalue's eigenvector.
  const Eigen::Vector3d c0 = r1.cross(r2), c1 = r2.cross(r0), c2 = r0.cross(r1);
  const double n0 = c0.squaredNorm(), n1 = c1.squaredNorm(), n2 = c2.squaredNorm();
  const double trace = s[0] + s[3] + s[5];
  const double best = std::max({n0, n1, n2});
  // Rank below 2: every 2x2 minor vanishes next to the matrix's scale.
  if (!(trace > 0) || best <= 1e-24 * trace * trace * trace * trace) return false;
  const Eigen::Vector3d first = n0 == best ? c0 : n1 == best ? c1 : c2;
  // A second step squares the ratio of the two smallest eigenvalues in the error.
  v = c0 * first.x() + c1 * first.y() + c2 * first.z();
  const double len = v.norm();
  if (!(len > 0)) return false;
  v /= len;
  return true;
}

constexpr double kMaxBlockF = 64.0;
constexpr double kNoiseFloor = 0.5e-3;  // m: below any depth sensor's noise, keeps exact planes comparable

void smooth_cell_normals(CellGrid& grid) {
  // Each planar cell's 13 values (members, n, p, pp, n * its mse, n * its bound; 0 for the
  // others), summed over 3 cells of a row and then over the column of three row sums, each sum
  // in raster order of its terms; then the block fits of all cells at once.
  const std::size_t n = padded_cells(grid.cells.size());
  std::vector<double>& buf = grid.row_sums;
  buf.resize((2 * kBlockSums + 3) * n);
  double* values = buf.data();
  double* rows = values + kBlockSums * n;
  double* own_normal = rows + kBlockSums * n;
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    const CellFit& f = grid.cells[i];
    const double p = f.planar ? 1.0 : 0.0, cnt = p * f.count;
    const double v[kBlockSums] = {p, cnt, p * f.sum_p.x(), p * f.sum_p.y(), p * f.sum_p.z(), p * f.sum_pp[0],
                                  p * f.sum_pp[1], p * f.sum_pp[2], p * f.sum_pp[3], p * f.sum_pp[4],
                                  p * f.sum_pp[5], p * (f.mse * f.count), p * (f.max_mse * f.count)};
    for (int k = 0; k < kBlockSums; ++k) values[k * n + i] = v[k];
    for (int k = 0; k < 3; ++k) own_normal[k * n + i] = f.normal(k);
  }
  std::vector<double>& blocks = grid.block_sums;
  blocks.resize(static_cast<std::size_t>(kBlockFields) * n);
  for (std::size_t i = grid.cells.size(); i < n; ++i) {  // the padding
    for (int k = 0; k < kBlockSums; ++k) blocks[k * n + i] = 0.0;
    for (int k = 0; k < 3; ++k) own_normal[k * n + i] = 0.0;
  }
  const int cols = grid.cols;
  for (int k = 0; k < kBlockSums; ++k)
    for (int cv = 0; cv < grid.rows; ++cv) {
      const double* v = values + k * n + static_cast<std::size_t>(cv) * cols;
      double* r = rows + k * n + static_cast<std::size_t>(cv) * cols;
      for (int cu = 0; cu < cols; ++cu) {
        double sum = cu > 0 ? v[cu - 1] + v[cu] : v[cu];
        if (cu + 1 < cols) sum += v[cu + 1];
        r[cu] = sum;
      }
    }
  for (int k = 0; k < kBlockSums; ++k)
    for (int cv = 0; cv < grid.rows; ++cv) {
      const double* r = rows + k * n + static_cast<std::size_t>(cv) * cols;
      double* b = blocks.data() + k * n + static_cast<std::size_t>(cv) * cols;
      const bool up = cv > 0, down = cv + 1 < grid.rows;
      for (int cu = 0; cu < cols; ++cu) {
        double sum = up ? r[cu - cols] + r[cu] : r[cu];
        if (down) sum += r[cu + cols];
        b[cu] = sum;
      }
    }
  // One plane must explain the block nearly as well as a plane per cell does: the residual it
  // adds, per degree of freedom given up, within kMaxBlockF of the cells' own noise variance
  // (an F test). Real depth noise is correlated within a cell (disparity terraces), so flat
  // real walls reach F of 10-30; an 8 mm step between exact cells gives about 1500 (measured
  // on resources/real-frames and cell_fits_test).
  fit_block_planes(blocks.data(), own_normal, n, kMaxBlockF, kNoiseFloor * kNoiseFloor);
  const double* b = blocks.data();
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    CellFit& cell = grid.cells[i];
    cell.block_normal = cell.normal;
    cell.block_se = cell.normal_se;
    cell.block_fitted = cell.planar && b[kBlockFitted * n + i] > 0;
    if (cell.block_fitted) {
      cell.block_normal = Eigen::Vector3d(b[kBlockNormalX * n + i], b[kBlockNormalY * n + i], b[kBlockNormalZ * n + i]);
      cell.block_se = b[kBlockSe * n + i];
    }
    // A cell planar only within the noise bound has too little extent for its own normal (at
    // 3 m an 8-pixel cell spans 4 cm against 1 cm of noise, and its fitted normal is off by
    // 70-80 degrees on the simulated end wall): it stays planar only with a block normal.
    if (cell.planar && !cell.quiet && !cell.block_fitted) cell.planar = false, cell.normal_se = M_PI;
  }
  admit_cells_facing_the_camera(grid, kMaxBlockF);
}

void compute_cell_fits(const OrganizedCloud& cloud, int cell_px, int min_valid, double max_rms_m,
                       CellGrid& grid, double noise_multiple) {
  const int c = std::max(2, cell_px);
  grid.cell_px = c;
  grid.cols = (cloud.width + c - 1) / c;
  grid.rows = (cloud.height + c - 1) / c;
  const std::size_t n = static_cast<std::size_t>(grid.cols) * grid.rows;
  grid.cells.resize(n);
  const std::size_t stride = padded_cells(n);
  grid.fit_arrays.resize(static_cast<std::size_t>(kCellFields) * stride);
  double* a = grid.fit_arrays.data();
  for (int k = 0; k < kMeanX; ++k) std::fill(a + k * stride + n, a + (k + 1) * stride, 0.0);  // the padding
  double m[11];
  for (int cv = 0; cv < grid.rows; ++cv) {
    const int v0 = cv * c, v1 = std::min(cloud.height, v0 + c);
    for (int cu = 0; cu < grid.cols; ++cu) {
      const int u0 = cu * c, u1 = std::min(cloud.width, u0 + c);
      const std::size_t i = static_cast<std::size_t>(grid.index(cu, cv));
      Eigen::Vector3f ref = Eigen::Vector3f::Zero();
      if (reference_point(cloud, u0, v0, u1, v1, ref)) cell_moments(cloud, u0, v0, u1, v1, ref, m);
      else std::fill(m, m + 11, 0.0);
      for (int k = 0; k < 11; ++k) a[(kMoment0 + k) * stride + i] = m[k];
      for (int k = 0; k < 3; ++k) a[(kRefX + k) * stride + i] = ref(k);
    }
  }
  fit_cell_planes(a, stride, std::max(3, min_valid));
  const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (std::size_t i = 0; i < n; ++i) {
    CellFit& cell = grid.cells[i];
    const double cnt = a[kMoment0 * stride + i];
    cell.count = static_cast<int>(cnt + 0.5);  // an exact count in a float sum
    // From locals: reading back the fields just stored stalls store forwarding (perf: a fifth
    // of this loop).
    const Eigen::Vector3d mean(a[kMeanX * stride + i], a[kMeanY * stride + i], a[kMeanZ * stride + i]);
    cell.mean = mean;
    cell.sum_p = cnt * mean;
    for (int k = 0; k < 6; ++k) {
      const double scatter = a[(kScatter0 + k) * stride + i];
      cell.scatter[k] = scatter;
      cell.sum_pp[k] = scatter + cnt * mean(ij[k][0]) * mean(ij[k][1]);
    }
    cell.sum_z3 = a[kSumZ3 * stride + i];
    cell.fitted = a[kFitted * stride + i] > 0;
    cell.normal = Eigen::Vector3d(a[kNormalX * stride + i], a[kNormalY * stride + i], a[kNormalZ * stride + i]);
    cell.mse = a[kMse * stride + i];
  }
  const double max_mse = max_rms_m * max_rms_m;
  for (std::size_t i = 0; i < n; ++i) {
    CellFit& cell = grid.cells[i];
    cell.quiet = cell.fitted && cell.mse <= max_mse;
    cell.normal_se = a[kNormalSe * stride + i];
  }
  grid.noise_per_m2 = noise_multiple > 0 ? noise_coefficient(grid, grid.ratios) : 0.0;
  grid.axial_noise_per_m2 = noise_multiple > 0 ? axial_noise_coefficient(grid, grid.ratios) : 0.0;
  grid.noise_multiple = noise_multiple;
  for (std::size_t i = 0; i < n; ++i) {
    CellFit& cell = grid.cells[i];
    const double noise = noise_multiple * grid.noise_per_m2 * cell.mean.z() * cell.mean.z();
    cell.max_mse = std::max(max_mse, noise * noise);
    cell.planar = cell.fitted && cell.mse <= cell.max_mse;
    // Only the growing reads it, and only of planar cells.
    if (!cell.planar) cell.normal_se = M_PI;
  }
}

}  // namespace tunnelmap
