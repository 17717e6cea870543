#pragma once
// The per-cell arithmetic of compute_cell_fits and smooth_cell_normals over arrays of cells
// (one array per quantity), on vectors of cells (GCC vector extensions): cell_fit_batch.cpp
// compiles them for four cells per instruction with AVX2 and two with SSE2. Cell by cell, the
// 3x3 eigenvector alone took a tenth of the frame's plane extraction on the real frames.
// The operations are those of the scalar smallest_eigenvector and normal_standard_error, in the
// same order, without fused multiply-adds: every lane gives the scalar code's bits.
#include <cmath>
#include <cstddef>
#include <cstring>

namespace tunnelmap {

// Fields of CellArrays, each an array over the cells.
enum CellField : int {
  kMoment0 = 0,                  // 11 moments about the reference point (cell_moments)
  kRefX = 11, kRefY, kRefZ,      // the reference point
  kMeanX, kMeanY, kMeanZ,        // outputs of fit_cell_planes from here on
  kScatter0,                     // 6: xx xy xz yy yz zz about the mean
  kNormalX = kScatter0 + 6, kNormalY, kNormalZ,  // unit, facing the camera
  kMse, kNormalSe, kSumZ3, kFitted,              // kFitted: 1 or 0
  kCellFields
};

// Fields of BlockArrays: the sums over each cell's 3x3 block of its planar members' values
// (smooth_cell_normals), then the block fit.
enum BlockField : int {
  kMembers = 0, kCount, kSumX, kSumY, kSumZ, kSumPP0,  // sum p p^T: 6 values
  kOwnResidual = kSumPP0 + 6, kBound,                   // sum of n * mse and of n * max_mse
  kBlockSums,                                           // 13 sums
  kBlockNormalX = kBlockSums, kBlockNormalY, kBlockNormalZ, kBlockSe, kBlockFitted,
  kBlockFields
};

// Arrays of cells are padded to a multiple of this many cells (the widest vector).
constexpr std::size_t kCellLanes = 4;
inline std::size_t padded_cells(std::size_t n) { return (n + kCellLanes - 1) / kCellLanes * kCellLanes; }

#define TM_INLINE inline __attribute__((always_inline))

template <typename V>
struct Lanes {
  static constexpr int kWidth = sizeof(V) / sizeof(double);
  using Mask = decltype(V() < V());
  static TM_INLINE V load(const double* p) {
    V v;
    std::memcpy(&v, p, sizeof(V));
    return v;
  }
  static TM_INLINE void store(double* p, V v) { std::memcpy(p, &v, sizeof(V)); }
  static TM_INLINE V splat(double x) {
    V v;
    for (int l = 0; l < kWidth; ++l) v[l] = x;
    return v;
  }
  static TM_INLINE V sqrt(V x) {
    for (int l = 0; l < kWidth; ++l) x[l] = __builtin_sqrt(x[l]);
    return x;
  }
  static TM_INLINE V max(V a, V b) { return a < b ? b : a; }  // std::max's choice
};

// smallest_eigenvector (cell_fits.h) for a vector of matrices: `ok` is all-ones in the lanes
// with a unique smallest eigenvector, returned in v (0 elsewhere).
template <typename V>
TM_INLINE typename Lanes<V>::Mask eigen_step(const V s[6], V v[3]) {
  using L = Lanes<V>;
  // Columns of the adjugate, as Eigen's cross products of the rows compute them.
  const V c0x = s[3] * s[5] - s[4] * s[4], c0y = s[4] * s[2] - s[1] * s[5], c0z = s[1] * s[4] - s[3] * s[2];
  const V c1x = s[4] * s[2] - s[5] * s[1], c1y = s[5] * s[0] - s[2] * s[2], c1z = s[2] * s[1] - s[4] * s[0];
  const V c2x = s[1] * s[4] - s[2] * s[3], c2y = s[2] * s[1] - s[0] * s[4], c2z = s[0] * s[3] - s[1] * s[1];
  const V n0 = c0x * c0x + c0y * c0y + c0z * c0z, n1 = c1x * c1x + c1y * c1y + c1z * c1z;
  const V n2 = c2x * c2x + c2y * c2y + c2z * c2z;
  const V trace = s[0] + s[3] + s[5];
  const V best = L::max(L::max(n0, n1), n2);
  const auto pick0 = n0 == best, pick1 = n1 == best;
  const V fx = pick0 ? c0x : pick1 ? c1x : c2x, fy = pick0 ? c0y : pick1 ? c1y : c2y;
  const V fz = pick0 ? c0z : pick1 ? c1z : c2z;
  const V vx = c0x * fx + c1x * fy + c2x * fz, vy = c0y * fx + c1y * fy + c2y * fz;
  const V vz = c0z * fx + c1z * fy + c2z * fz;
  const V len = L::sqrt(vx * vx + vy * vy + vz * vz);
  const V zero = L::splat(0.0), tiny = L::splat(1e-24);
  const auto ok = (trace > zero) & (best > tiny * trace * trace * trace * trace) & (len > zero);
  const V l = ok ? len : L::splat(1.0);
  v[0] = ok ? vx / l : zero, v[1] = ok ? vy / l : zero, v[2] = ok ? vz / l : zero;
  return ok;
}

// n^T S n for a symmetric S given as xx xy xz yy yz zz, in mse_to's order.
template <typename V>
TM_INLINE V quadratic_form(const V s[6], const V n[3]) {
  return n[0] * (n[0] * s[0] + 2 * n[1] * s[1] + 2 * n[2] * s[2]) + n[1] * (n[1] * s[3] + 2 * n[2] * s[4]) +
         n[2] * n[2] * s[5];
}

// normal_standard_error (cell_fits.cpp) for a vector of fits.
template <typename V>
TM_INLINE V normal_error(const V s[6], V l0, V cnt) {
  using L = Lanes<V>;
  const V zero = L::splat(0.0);
  const V t = s[0] + s[3] + s[5];
  const V minors = s[0] * s[3] - s[1] * s[1] + s[0] * s[5] - s[2] * s[2] + s[3] * s[5] - s[4] * s[4];
  const V sum12 = t - l0, prod12 = minors - l0 * sum12;
  const V l1 = 0.5 * (sum12 - L::sqrt(L::max(zero, sum12 * sum12 - 4 * prod12)));
  const auto ok = (cnt > L::splat(3.0)) & (l1 > zero);
  return ok ? L::sqrt(l0 / ((cnt - 3) * (ok ? l1 : L::splat(1.0)))) : L::splat(M_PI);
}

// For the cells of `a` (kCellFields arrays of `stride` values, a multiple of kCellLanes):
// mean, scatter, plane, mse, normal standard error (as if planar) and the z^3 sum from the
// moments; kFitted is 1 for a cell of at least `min_points` points with a unique normal.
template <typename V>
TM_INLINE void fit_cell_planes_kernel(double* a, std::size_t stride, double min_points) {
  using L = Lanes<V>;
  const auto f = [&](int k, std::size_t i) { return a + k * stride + i; };
  const V zero = L::splat(0.0), one = L::splat(1.0);
  for (std::size_t i = 0; i < stride; i += L::kWidth) {
    const V cnt = L::load(f(kMoment0, i));
    const auto any = cnt > zero;
    const V inv = any ? one / (any ? cnt : one) : zero;
    const V m3 = L::load(f(kMoment0 + 3, i)), m9 = L::load(f(kMoment0 + 9, i));
    const V d[3] = {L::load(f(kMoment0 + 1, i)) * inv, L::load(f(kMoment0 + 2, i)) * inv, m3 * inv};
    const V mean[3] = {L::load(f(kRefX, i)) + d[0], L::load(f(kRefY, i)) + d[1], L::load(f(kRefZ, i)) + d[2]};
    V s[6];
    s[0] = L::load(f(kMoment0 + 4, i)) - cnt * d[0] * d[0], s[1] = L::load(f(kMoment0 + 5, i)) - cnt * d[0] * d[1];
    s[2] = L::load(f(kMoment0 + 6, i)) - cnt * d[0] * d[2], s[3] = L::load(f(kMoment0 + 7, i)) - cnt * d[1] * d[1];
    s[4] = L::load(f(kMoment0 + 8, i)) - cnt * d[1] * d[2], s[5] = m9 - cnt * d[2] * d[2];
    const V rz = L::load(f(kRefZ, i));
    L::store(f(kSumZ3, i), cnt * rz * rz * rz + 3 * rz * rz * m3 + 3 * rz * m9 + L::load(f(kMoment0 + 10, i)));
    V v[3];
    const auto ok = eigen_step(s, v);
    const auto away = v[0] * mean[0] + v[1] * mean[1] + v[2] * mean[2] > zero;  // face the camera
    for (V& c : v) c = away ? -c : c;
    // The plane passes through the mean: mse_to's offset term is exactly 0.
    const V mse = L::max(zero, quadratic_form(s, v) / (any ? cnt : one));
    const auto fitted = ok & (cnt >= L::splat(min_points));
    for (int k = 0; k < 3; ++k) L::store(f(kMeanX + k, i), mean[k]), L::store(f(kNormalX + k, i), fitted ? v[k] : zero);
    for (int k = 0; k < 6; ++k) L::store(f(kScatter0 + k, i), s[k]);
    L::store(f(kMse, i), fitted ? mse : zero);
    L::store(f(kNormalSe, i), normal_error(s, mse * cnt, cnt));
    L::store(f(kFitted, i), fitted ? one : zero);
  }
}

// For the cells of `b` (kBlockFields arrays of `stride` values, a multiple of kCellLanes, the
// 13 sums filled in): the block's least-squares normal, accepted when its spread stays within
// the members' bounds and one plane explains the block nearly as well as one per cell (an F
// test within `max_f` of the cells' own noise variance, at least `noise_floor2`). The normal
// faces like the cell's own (`own_normal`, 3 arrays of `stride`).
template <typename V>
TM_INLINE void fit_block_planes_kernel(double* b, const double* own_normal, std::size_t stride, double max_f,
                                       double noise_floor2) {
  using L = Lanes<V>;
  const auto f = [&](int k, std::size_t i) { return b + k * stride + i; };
  const V zero = L::splat(0.0), one = L::splat(1.0);
  for (std::size_t i = 0; i < stride; i += L::kWidth) {
    const V members = L::load(f(kMembers, i)), cnt = L::load(f(kCount, i));
    const V c = cnt > zero ? cnt : one;
    const V mean[3] = {L::load(f(kSumX, i)) / c, L::load(f(kSumY, i)) / c, L::load(f(kSumZ, i)) / c};
    V s[6];
    s[0] = L::load(f(kSumPP0, i)) - cnt * mean[0] * mean[0];
    s[1] = L::load(f(kSumPP0 + 1, i)) - cnt * mean[0] * mean[1];
    s[2] = L::load(f(kSumPP0 + 2, i)) - cnt * mean[0] * mean[2];
    s[3] = L::load(f(kSumPP0 + 3, i)) - cnt * mean[1] * mean[1];
    s[4] = L::load(f(kSumPP0 + 4, i)) - cnt * mean[1] * mean[2];
    s[5] = L::load(f(kSumPP0 + 5, i)) - cnt * mean[2] * mean[2];
    V v[3];
    const auto ok = eigen_step(s, v);
    const V spread = quadratic_form(s, v);
    const V own = L::load(f(kOwnResidual, i));
    const V dof = L::max(one, cnt - 3 * members);
    const V noise = L::max(own / dof, L::splat(noise_floor2));
    const auto fitted = (members >= L::splat(2.0)) & ok & ~(spread > L::load(f(kBound, i))) &
                        ~((spread - own) / (3 * (members - 1)) > L::splat(max_f) * noise);
    const auto opposite = v[0] * L::load(own_normal + i) + v[1] * L::load(own_normal + stride + i) +
                              v[2] * L::load(own_normal + 2 * stride + i) < zero;
    for (int k = 0; k < 3; ++k) L::store(f(kBlockNormalX + k, i), opposite ? -v[k] : v[k]);
    L::store(f(kBlockSe, i), normal_error(s, L::max(zero, spread), cnt));
    L::store(f(kBlockFitted, i), fitted ? one : zero);
  }
}

#undef TM_INLINE

}  // namespace tunnelmap
