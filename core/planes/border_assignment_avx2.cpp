#include "core/planes/border_assignment_avx2.h"

#include <immintrin.h>


#include "core/planes/border_assignment_parts.h"
#include "core/util/avx2_dispatch.h"
#include "core/util/avx2_xyz.h"

namespace tunnelmap {

namespace {
Avx2Dispatch dispatch;
}  // namespace

bool border_assignment_avx2_available() { return dispatch.use_avx2(); }
void force_sse_border_assignment(bool on) { dispatch.force_sse(on); }

namespace {

#define TM_AVX2 __attribute__((target("avx2")))

constexpr int kMaxCandidates = 9;
constexpr int kAnyCount = 0;

TM_AVX2 double hsum8(__m256 v) {
  const __m128 s = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  const __m128 t = _mm_add_ps(s, _mm_movehl_ps(s, s));
  return _mm_cvtss_f32(_mm_add_ss(t, _mm_shuffle_ps(t, t, 1)));
}

// The kernel for `N` candidates (compile-time N keeps the sums in registers; kAnyCount reads
// the count at run time). Distances and the nearest plane are computed in load_xyz8's lane
// order; the labels are put back in pixel order to be stored and to mark columns.
template <int N>
TM_AVX2 void assign_cell(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, const Eigen::Vector4f* planes,
                         const std::int32_t* cand, int ncand_runtime, float eps, std::int32_t* labels,
                         PixelTally* tallies) {
  using namespace border_assignment;
  const int ncand = N == kAnyCount ? ncand_runtime : N;
  constexpr int M = N == kAnyCount ? kMaxCandidates : N;
  __m256 nx[M], ny[M], nz[M], nd[M];
  __m256i id[M];
  __m256 sn[M], sx[M], sy[M], sz[M], sz3[M];
  ScalarSums tail[M];
  WonBox box[M];
  for (int k = 0; k < ncand; ++k) {
    const Eigen::Vector4f& a = planes[cand[k] - 1];
    nx[k] = _mm256_set1_ps(a.x()), ny[k] = _mm256_set1_ps(a.y()), nz[k] = _mm256_set1_ps(a.z());
    nd[k] = _mm256_set1_ps(a.w());
    id[k] = _mm256_set1_epi32(cand[k]);
    sn[k] = sx[k] = sy[k] = sz[k] = sz3[k] = _mm256_setzero_ps();
  }
  const __m256 eps8 = _mm256_set1_ps(eps), abs_mask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256i pixel_order = xyz8_pixel_order();
  for (int v = v0; v < v1; ++v) {
    const float* p = cloud.points[cloud.index(0, v)].data();
    std::int32_t* l = labels + cloud.index(0, v);
    std::uint32_t row_bits[M];
    for (int k = 0; k < ncand; ++k) row_bits[k] = 0;
    int u = u0;
    for (; u + 8 <= u1; u += 8) {
      __m256 x, y, z;
      load_xyz8(p + 3 * u, x, y, z);
      __m256 best_d = eps8;
      __m256i best = _mm256_setzero_si256();
      for (int k = 0; k < ncand; ++k) {
        const __m256 d = _mm256_and_ps(
            abs_mask, _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nx[k], x), _mm256_mul_ps(ny[k], y)),
                                    _mm256_add_ps(_mm256_mul_ps(nz[k], z), nd[k])));
        const __m256 closer = _mm256_cmp_ps(d, best_d, _CMP_LE_OQ);  // false for NaN (invalid pixels)
        best_d = _mm256_blendv_ps(best_d, d, closer);
        best = _mm256_blendv_epi8(best, id[k], _mm256_castps_si256(closer));
      }
      const __m256i in_pixel_order = _mm256_permutevar8x32_epi32(best, pixel_order);
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(l + u), in_pixel_order);
      const __m256 z3 = _mm256_mul_ps(_mm256_mul_ps(z, z), z);
      for (int k = 0; k < ncand; ++k) {
        const __m256 won = _mm256_castsi256_ps(_mm256_cmpeq_epi32(best, id[k]));
        const __m256 won_px = _mm256_castsi256_ps(_mm256_cmpeq_epi32(in_pixel_order, id[k]));
        row_bits[k] |= static_cast<std::uint32_t>(_mm256_movemask_ps(won_px)) << (u - u0);
        sn[k] = _mm256_add_ps(sn[k], _mm256_and_ps(won, one));
        sx[k] = _mm256_add_ps(sx[k], _mm256_and_ps(won, x)), sy[k] = _mm256_add_ps(sy[k], _mm256_and_ps(won, y));
        sz[k] = _mm256_add_ps(sz[k], _mm256_and_ps(won, z)), sz3[k] = _mm256_add_ps(sz3[k], _mm256_and_ps(won, z3));
      }
    }
    assign_row_tail(p, u, u1, u0, planes, cand, ncand, eps, l, row_bits, tail);
    for (int k = 0; k < ncand; ++k) box[k].add_row(row_bits[k], v);
  }
  for (int k = 0; k < ncand; ++k)
    add_to_tally(tallies[cand[k] - 1], {hsum8(sn[k]), hsum8(sx[k]), hsum8(sy[k]), hsum8(sz[k]), hsum8(sz3[k])},
                 tail[k], u0, box[k]);
}

}  // namespace

void assign_to_nearest_plane_avx2(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1,
                                  const Eigen::Vector4f* planes, const std::int32_t* cand, int ncand, float eps,
                                  std::int32_t* labels, PixelTally* tallies) {
  switch (ncand) {
    case 1: return assign_cell<1>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 2: return assign_cell<2>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 3: return assign_cell<3>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    case 4: return assign_cell<4>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
    default: return assign_cell<kAnyCount>(cloud, u0, v0, u1, v1, planes, cand, ncand, eps, labels, tallies);
  }
}

}  // namespace tunnelmap
