#pragma once
// What the SSE and AVX2 border-assignment kernels share: the scalar step for a row's last
// pixels, the columns and rows each candidate won, and the tally they end in.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "core/planes/border_assignment.h"

namespace tunnelmap::border_assignment {

// Index in `cand` of the nearest candidate plane within eps (the last of equals), or -1, also
// for an invalid (NaN) point.
inline int nearest_candidate(const Eigen::Vector4f* planes, const std::int32_t* cand, int ncand, float eps, float x,
                             float y, float z) {
  int best = -1;
  float best_d = eps;
  for (int k = 0; k < ncand; ++k) {
    const Eigen::Vector4f& a = planes[cand[k] - 1];
    const float d = std::abs(a.x() * x + a.y() * y + a.z() * z + a.w());
    if (d <= best_d) best_d = d, best = k;  // false for NaN
  }
  return best;
}

// Sums of the pixels a candidate won by the scalar step: x, y, z, z^3 (the count is the
// popcount of the columns won, WonBox).
struct ScalarSums {
  float s[4] = {0, 0, 0, 0};
  void add(float x, float y, float z) { s[0] += x, s[1] += y, s[2] += z, s[3] += z * z * z; }
};

// The columns (bits from the cell's first column, at most 32) and rows a candidate won, and
// how many pixels.
struct WonBox {
  std::uint32_t cols = 0;
  int row0 = -1, row1 = -1;
  int count = 0;
  void add_row(std::uint32_t bits, int v) {
    if (bits == 0) return;
    cols |= bits;
    count += __builtin_popcount(bits);
    if (row0 < 0) row0 = v;
    row1 = v;
  }
};

// The scalar step for pixels [u, u1) of a row (those the vector step left over): labels,
// columns won (bits from column u0) and sums.
inline void assign_row_tail(const float* row, int u, int u1, int u0, const Eigen::Vector4f* planes,
                            const std::int32_t* cand, int ncand, float eps, std::int32_t* labels,
                            std::uint32_t* row_bits, ScalarSums* tail) {
  for (; u < u1; ++u) {
    const float* q = row + 3 * u;
    const int k = nearest_candidate(planes, cand, ncand, eps, q[0], q[1], q[2]);
    labels[u] = k < 0 ? 0 : cand[k];
    if (k < 0) continue;
    row_bits[k] |= 1u << (u - u0);
    tail[k].add(q[0], q[1], q[2]);
  }
}

// Adds what a candidate won in the cell starting at column u0 to its plane's tally: the pixels,
// the vector step's sums (x, y, z, z^3) and the scalar step's.
inline void add_to_tally(PixelTally& t, const float* vector_sums, const ScalarSums& tail, int u0, const WonBox& b) {
  if (b.cols == 0) return;
  const float* v = vector_sums;
  const float* s = tail.s;
  t.count += b.count;
  t.sum_p += Eigen::Vector3d(double(v[0]) + s[0], double(v[1]) + s[1], double(v[2]) + s[2]);
  t.sum_z3 += double(v[3]) + s[3];
  t.include_box(u0 + __builtin_ctz(b.cols), b.row0, u0 + 31 - __builtin_clz(b.cols), b.row1);
}

}  // namespace tunnelmap::border_assignment
