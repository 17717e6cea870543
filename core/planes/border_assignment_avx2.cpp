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

// The lane sums of v[0..7] as one vector (lane k = the sum of v[k]), stored to out[0..7].
TM_AVX2 void lane_sums8(const __m256* v, float* out) {
  const __m256 a = _mm256_hadd_ps(_mm256_hadd_ps(v[0], v[1]), _mm256_hadd_ps(v[2], v[3]));
  const __m256 b = _mm256_hadd_ps(_mm256_hadd_ps(v[4], v[5]), _mm256_hadd_ps(v[6], v[7]));
  _mm256_storeu_ps(out, _mm256_add_ps(_mm256_permute2f128_ps(a, b, 0x20), _mm256_permute2f128_ps(a, b, 0x31)));
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
  // Per candidate x, y, z, z^3 (padded to whole groups of 8 for the reduction).
  __m256 sums[4 * M + 4];
  ScalarSums tail[M];
  WonBox box[M];
  for (int k = 0; k < ncand; ++k) {
    const Eigen::Vector4f& a = planes[cand[k] - 1];
    nx[k] = _mm256_set1_ps(a.x()), ny[k] = _mm256_set1_ps(a.y()), nz[k] = _mm256_set1_ps(a.z());
    nd[k] = _mm256_set1_ps(a.w());
    id[k] = _mm256_set1_epi32(cand[k]);
  }
  for (int k = 0; k < 4 * ncand + 4; ++k) sums[k] = _mm256_setzero_ps();
  const __m256 eps8 = _mm256_set1_ps(eps), abs_mask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
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
        __m256* sk = sums + 4 * k;
        sk[0] = _mm256_add_ps(sk[0], _mm256_and_ps(won, x)), sk[1] = _mm256_add_ps(sk[1], _mm256_and_ps(won, y));
        sk[2] = _mm256_add_ps(sk[2], _mm256_and_ps(won, z)), sk[3] = _mm256_add_ps(sk[3], _mm256_and_ps(won, z3));
      }
    }
    assign_row_tail(p, u, u1, u0, planes, cand, ncand, eps, l, row_bits, tail);
    for (int k = 0; k < ncand; ++k) box[k].add_row(row_bits[k], v);
  }
  float reduced[4 * M + 8];
  for (int g = 0; g < 4 * ncand; g += 8) lane_sums8(sums + g, reduced + g);
  for (int k = 0; k < ncand; ++k) add_to_tally(tallies[cand[k] - 1], reduced + 4 * k, tail[k], u0, box[k]);
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
