#include "core/planes/border_assignment.h"

#include <algorithm>
#include <cmath>
#include <emmintrin.h>

#include "core/planes/border_assignment_avx2.h"
#include "core/planes/border_assignment_parts.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {

float horizontal_sum(__m128 v) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return (f[0] + f[1]) + (f[2] + f[3]);
}


}  // namespace

void PixelTally::include_box(int bu0, int bv0, int bu1, int bv1) {
  if (u1 < u0) {
    u0 = bu0, v0 = bv0, u1 = bu1, v1 = bv1;
    return;
  }
  u0 = std::min(u0, bu0), v0 = std::min(v0, bv0), u1 = std::max(u1, bu1), v1 = std::max(v1, bv1);
}

namespace {

// The kernel for `N` candidates (a compile-time count keeps the per-candidate sums in
// registers; N = kAnyCount reads the count at run time).
constexpr int kMaxCandidates = 9;
constexpr int kAnyCount = 0;

template <int N>
void assign_cell(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, const Eigen::Vector4f* planes,
                 const std::int32_t* cand, int ncand_runtime, float eps, std::int32_t* labels, PixelTally* tallies) {
  using namespace border_assignment;
  const int ncand = N == kAnyCount ? ncand_runtime : N;
  constexpr int M = N == kAnyCount ? kMaxCandidates : N;
  __m128 nx[M], ny[M], nz[M], nd[M];
  __m128i id[M];
  // Per candidate: float sums over the cell (a few hundred points at most: float keeps them to
  // well under a micrometre), and the columns and rows it won.
  __m128 sx[M], sy[M], sz[M], sz3[M];
  ScalarSums tail[M];
  WonBox box[M];
  for (int k = 0; k < ncand; ++k) {
    const Eigen::Vector4f& a = planes[cand[k] - 1];
    nx[k] = _mm_set1_ps(a.x()), ny[k] = _mm_set1_ps(a.y()), nz[k] = _mm_set1_ps(a.z()), nd[k] = _mm_set1_ps(a.w());
    id[k] = _mm_set1_epi32(cand[k]);
    sx[k] = sy[k] = sz[k] = sz3[k] = _mm_setzero_ps();
  }
  const __m128 eps4 = _mm_set1_ps(eps), abs_mask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  for (int v = v0; v < v1; ++v) {
    const float* p = cloud.points[cloud.index(0, v)].data();
    std::int32_t* l = labels + cloud.index(0, v);
    std::uint32_t row_bits[M];
    for (int k = 0; k < ncand; ++k) row_bits[k] = 0;
    int u = u0;
    for (; u + 4 <= u1; u += 4) {
      __m128 x, y, z;
      load_xyz4(p + 3 * u, x, y, z);
      __m128 best_d = eps4;
      __m128i best = _mm_setzero_si128();
      for (int k = 0; k < ncand; ++k) {
        const __m128 d = _mm_and_ps(abs_mask, _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx[k], x), _mm_mul_ps(ny[k], y)),
                                                          _mm_add_ps(_mm_mul_ps(nz[k], z), nd[k])));
        const __m128 closer = _mm_cmple_ps(d, best_d);  // false for NaN (invalid pixels)
        best_d = _mm_or_ps(_mm_and_ps(closer, d), _mm_andnot_ps(closer, best_d));
        const __m128i c = _mm_castps_si128(closer);
        best = _mm_or_si128(_mm_and_si128(c, id[k]), _mm_andnot_si128(c, best));
      }
      _mm_storeu_si128(reinterpret_cast<__m128i*>(l + u), best);
      const __m128 z3 = _mm_mul_ps(_mm_mul_ps(z, z), z);
      for (int k = 0; k < ncand; ++k) {
        const __m128 won = _mm_castsi128_ps(_mm_cmpeq_epi32(best, id[k]));
        row_bits[k] |= static_cast<std::uint32_t>(_mm_movemask_ps(won)) << (u - u0);
        sx[k] = _mm_add_ps(sx[k], _mm_and_ps(won, x)), sy[k] = _mm_add_ps(sy[k], _mm_and_ps(won, y));
        sz[k] = _mm_add_ps(sz[k], _mm_and_ps(won, z)), sz3[k] = _mm_add_ps(sz3[k], _mm_and_ps(won, z3));
      }
    }
    assign_row_tail(p, u, u1, u0, planes, cand, ncand, eps, l, row_bits, tail);
    for (int k = 0; k < ncand; ++k) box[k].add_row(row_bits[k], v);
  }
  for (int k = 0; k < ncand; ++k) {
    const float sums[4] = {horizontal_sum(sx[k]), horizontal_sum(sy[k]), horizontal_sum(sz[k]),
                           horizontal_sum(sz3[k])};
    add_to_tally(tallies[cand[k] - 1], sums, tail[k], u0, box[k]);
  }
}

}  // namespace

void assign_to_nearest_plane(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1,
                             const Eigen::Vector4f* planes, const std::int32_t* cand, int ncand, float eps,
                             std::int32_t* labels, PixelTally* tallies) {
  if (u1 - u0 >= 8 && border_assignment_avx2_available())
    return assign_to_nearest_plane_avx2(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
  switch (ncand) {
    case 1: return assign_cell<1>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 2: return assign_cell<2>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 3: return assign_cell<3>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 4: return assign_cell<4>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    default: return assign_cell<kAnyCount>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
  }
}

}  // namespace tunnelmap
