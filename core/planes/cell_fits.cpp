#include "core/planes/cell_fits.h"

#include <Eigen/Geometry>  // cross
#include <algorithm>
#include <cmath>

#include <emmintrin.h>

#include "core/planes/cell_moments_avx2.h"
#include "core/planes/cell_moments_tail.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {

float hsum(__m128 a) {
  const __m128 s = _mm_add_ps(a, _mm_movehl_ps(a, a));
  return _mm_cvtss_f32(_mm_add_ss(s, _mm_shuffle_ps(s, s, 1)));
}

// Standard error of a fitted normal (radians) from the scatter about the mean and the residual
// along the normal: sigma / sqrt(L1), the normal tilts most towards the plane's narrower
// in-plane direction; sigma^2 = L0 / (n - 3), L0 <= L1 <= L2 the scatter's eigenvalues.
double normal_standard_error(const double scatter[6], double l0, double cnt) {
  const double* s = scatter;
  const double t = s[0] + s[3] + s[5];
  const double minors = s[0] * s[3] - s[1] * s[1] + s[0] * s[5] - s[2] * s[2] + s[3] * s[5] - s[4] * s[4];
  const double sum12 = t - l0, prod12 = minors - l0 * sum12;
  const double l1 = 0.5 * (sum12 - std::sqrt(std::max(0.0, sum12 * sum12 - 4 * prod12)));
  return (cnt > 3 && l1 > 0) ? std::sqrt(l0 / ((cnt - 3) * l1)) : M_PI;
}

// A valid point of the cell to take moments about: its centre pixel, else the first valid one.
bool reference_point(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, Eigen::Vector3f& ref) {
  const Eigen::Vector3f& c = cloud.points[cloud.index((u0 + u1) / 2, (v0 + v1) / 2)];
  if (OrganizedCloud::valid(c)) return ref = c, true;
  for (int v = v0; v < v1; ++v)
    for (int u = u0; u < u1; ++u) {
      const Eigen::Vector3f& p = cloud.points[cloud.index(u, v)];
      if (OrganizedCloud::valid(p)) return ref = p, true;
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

// The cell's moments, mean and least-squares plane (normal and mse); planarity comes later.
void fit_cell(const double m[11], const Eigen::Vector3f& ref_f, int min_valid, CellFit& c) {
  c.count = static_cast<int>(std::lround(m[0]));
  c.fitted = c.quiet = c.planar = false;
  c.normal.setZero();
  c.mse = 0.0;
  if (c.count == 0) {
    c.sum_p.setZero(), c.mean.setZero(), c.sum_z3 = 0.0;
    std::fill(c.sum_pp, c.sum_pp + 6, 0.0), std::fill(c.scatter, c.scatter + 6, 0.0);
    return;
  }
  const double cnt = c.count;
  const Eigen::Vector3d ref = ref_f.cast<double>();
  const Eigen::Vector3d d(m[1] / cnt, m[2] / cnt, m[3] / cnt);  // mean offset from ref
  c.mean = ref + d;
  c.sum_p = cnt * c.mean;
  // About the mean: sum d d^T - n dbar dbar^T; about the origin: that + n mean mean^T.
  const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (int k = 0; k < 6; ++k) {
    const int i = ij[k][0], j = ij[k][1];
    c.scatter[k] = m[4 + k] - cnt * d(i) * d(j);
    c.sum_pp[k] = c.scatter[k] + cnt * c.mean(i) * c.mean(j);
  }
  // sum (rz + dz)^3 expanded.
  const double rz = ref.z();
  c.sum_z3 = cnt * rz * rz * rz + 3 * rz * rz * m[3] + 3 * rz * m[9] + m[10];
  if (c.count < std::max(3, min_valid)) return;
  Eigen::Vector3d nrm;
  if (!smallest_eigenvector(c.scatter, nrm)) return;
  if (nrm.dot(c.mean) > 0) nrm = -nrm;  // face the camera
  c.mse = std::max(0.0, c.mse_to(nrm, -nrm.dot(c.mean)));  // rounding can dip below 0 on an exact plane
  c.normal = nrm;
  c.fitted = true;
}

// The frame's depth noise as sigma = c z^2 (a structured-light sensor's disparity noise grows
// with the square of the range): c is the lower quartile of the fitted cells' RMS / z^2. Flat
// surfaces set it in any scene with some flat surface at some range; edges and clutter only
// raise the upper quantiles. 0 with too few fitted cells to tell.
double noise_coefficient(const CellGrid& grid, std::vector<double>& ratios) {
  constexpr double kQuantile = 0.25;
  constexpr std::size_t kMinCells = 16;
  ratios.clear();
  for (const CellFit& c : grid.cells)
    if (c.fitted && c.mean.z() > 0) ratios.push_back(std::sqrt(c.mse) / (c.mean.z() * c.mean.z()));
  if (ratios.size() < kMinCells) return 0.0;
  const auto q = ratios.begin() + static_cast<std::ptrdiff_t>(kQuantile * static_cast<double>(ratios.size() - 1));
  std::nth_element(ratios.begin(), q, ratios.end());
  return *q;
}

}  // namespace

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
  // Row sums over 3 cells of each planar cell's count, point and product sums, residual and
  // bound (13 values: members, n, p, pp, squared distances to its own plane, n * max_mse), then
  // the column of three row sums: 6 adds per value instead of 9.
  constexpr int kSums = 13;
  std::vector<double>& rows = grid.row_sums;
  rows.assign(grid.cells.size() * kSums, 0.0);
  for (int cv = 0; cv < grid.rows; ++cv)
    for (int cu = 0; cu < grid.cols; ++cu) {
      const CellFit& f = grid.cells[grid.index(cu, cv)];
      if (!f.planar) continue;
      const double v[kSums] = {1.0, static_cast<double>(f.count), f.sum_p.x(), f.sum_p.y(), f.sum_p.z(),
                               f.sum_pp[0], f.sum_pp[1], f.sum_pp[2], f.sum_pp[3], f.sum_pp[4], f.sum_pp[5],
                               f.mse * f.count, f.max_mse * f.count};
      for (int nu = std::max(0, cu - 1); nu <= std::min(grid.cols - 1, cu + 1); ++nu) {
        double* r = rows.data() + static_cast<std::size_t>(grid.index(nu, cv)) * kSums;
        for (int k = 0; k < kSums; ++k) r[k] += v[k];
      }
    }
  for (int cv = 0; cv < grid.rows; ++cv) {
    for (int cu = 0; cu < grid.cols; ++cu) {
      CellFit& cell = grid.cells[grid.index(cu, cv)];
      cell.block_normal = cell.normal;
      cell.block_se = cell.normal_se;
      cell.block_fitted = false;
      if (!cell.planar) continue;
      double b[kSums] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (int nv = std::max(0, cv - 1); nv <= std::min(grid.rows - 1, cv + 1); ++nv) {
        const double* r = rows.data() + static_cast<std::size_t>(grid.index(cu, nv)) * kSums;
        for (int k = 0; k < kSums; ++k) b[k] += r[k];
      }
      if (b[0] < 2) continue;
      const double cnt = b[1];
      const Eigen::Vector3d mean(b[2] / cnt, b[3] / cnt, b[4] / cnt);
      const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
      double scatter[6];
      for (int k = 0; k < 6; ++k) scatter[k] = b[5 + k] - cnt * mean(ij[k][0]) * mean(ij[k][1]);
      Eigen::Vector3d n;
      if (!smallest_eigenvector(scatter, n)) continue;
      const double spread = n.x() * (n.x() * scatter[0] + 2 * n.y() * scatter[1] + 2 * n.z() * scatter[2]) +
                            n.y() * (n.y() * scatter[3] + 2 * n.z() * scatter[4]) + n.z() * n.z() * scatter[5];
      if (spread > b[12]) continue;  // beyond the members' planarity bounds
      // One plane must explain the block nearly as well as a plane per cell does: the residual
      // it adds, per degree of freedom given up, within kMaxBlockF of the cells' own noise
      // variance (an F test). Real depth noise is correlated within a cell (disparity
      // terraces), so flat real walls reach F of 10-30; an 8 mm step between exact cells gives
      // about 1500 (measured on resources/real-frames and cell_fits_test).
      const double members = b[0], own = b[11];
      const double noise = std::max(own / std::max(1.0, cnt - 3 * members), kNoiseFloor * kNoiseFloor);
      if ((spread - own) / (3 * (members - 1)) > kMaxBlockF * noise) continue;  // keep the cell's own
      if (n.dot(cell.normal) < 0) n = -n;
      cell.block_normal = n;
      cell.block_se = normal_standard_error(scatter, std::max(0.0, spread), cnt);
      cell.block_fitted = true;
    }
  }
  // A cell planar only within the noise bound has too little extent for its own normal (at 3 m
  // an 8-pixel cell spans 4 cm against 1 cm of noise, and its fitted normal is off by 70-80
  // degrees on the simulated end wall): it stays planar only with a block plane's normal.
  for (CellFit& cell : grid.cells)
    if (cell.planar && !cell.quiet && !cell.block_fitted) cell.planar = false, cell.normal_se = M_PI;
}

void compute_cell_fits(const OrganizedCloud& cloud, int cell_px, int min_valid, double max_rms_m,
                       CellGrid& grid, double noise_multiple) {
  const int c = std::max(2, cell_px);
  grid.cell_px = c;
  grid.cols = (cloud.width + c - 1) / c;
  grid.rows = (cloud.height + c - 1) / c;
  grid.cells.resize(static_cast<std::size_t>(grid.cols) * grid.rows);
  double m[11];
  for (int cv = 0; cv < grid.rows; ++cv) {
    const int v0 = cv * c, v1 = std::min(cloud.height, v0 + c);
    for (int cu = 0; cu < grid.cols; ++cu) {
      const int u0 = cu * c, u1 = std::min(cloud.width, u0 + c);
      CellFit& cell = grid.cells[grid.index(cu, cv)];
      Eigen::Vector3f ref;
      if (!reference_point(cloud, u0, v0, u1, v1, ref)) {
        std::fill(m, m + 11, 0.0);
        fit_cell(m, Eigen::Vector3f::Zero(), min_valid, cell);
        continue;
      }
      cell_moments(cloud, u0, v0, u1, v1, ref, m);
      fit_cell(m, ref, min_valid, cell);
    }
  }
  const double max_mse = max_rms_m * max_rms_m;
  grid.noise_per_m2 = noise_multiple > 0 ? noise_coefficient(grid, grid.ratios) : 0.0;
  for (CellFit& cell : grid.cells) {
    const double noise = noise_multiple * grid.noise_per_m2 * cell.mean.z() * cell.mean.z();
    cell.max_mse = std::max(max_mse, noise * noise);
    cell.quiet = cell.fitted && cell.mse <= max_mse;
    cell.planar = cell.fitted && cell.mse <= cell.max_mse;
    // Only the growing reads it, and only of planar cells.
    cell.normal_se = cell.planar ? normal_standard_error(cell.scatter, cell.mse * cell.count, cell.count) : M_PI;
  }
}

}  // namespace tunnelmap
