#include "core/normals/normals_row_avx2.h"

#include <immintrin.h>

#include <cstring>
#include <limits>

#include "core/util/avx2_dispatch.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {
Avx2Dispatch dispatch;
}  // namespace

bool normals_avx2_available() { return dispatch.use_avx2(); }
void force_sse_normals(bool on) { dispatch.force_sse(on); }

namespace {

#define TM_AVX2 __attribute__((target("avx2")))

struct Means8 {
  __m256 x, y, z, s;
};

TM_AVX2 inline __m256 select8(__m256 mask, __m256 a, __m256 b) {  // mask ? a : b, as the SSE step
  return _mm256_or_ps(_mm256_and_ps(mask, a), _mm256_andnot_ps(mask, b));
}

TM_AVX2 inline Means8 load8(const float* const planes[4], int u) {
  return {_mm256_loadu_ps(planes[0] + u), _mm256_loadu_ps(planes[1] + u), _mm256_loadu_ps(planes[2] + u),
          _mm256_cmp_ps(_mm256_loadu_ps(planes[3] + u), _mm256_setzero_ps(), _CMP_GT_OQ)};
}

// Central tangent where both sides have support, else one-sided against the centre.
TM_AVX2 inline void tangent8(const Means8& a, const Means8& c, const Means8& b, __m256& tx, __m256& ty,
                             __m256& tz, __m256& ok) {
  ok = _mm256_or_ps(_mm256_and_ps(a.s, b.s), _mm256_and_ps(c.s, _mm256_or_ps(a.s, b.s)));
  tx = _mm256_sub_ps(select8(b.s, b.x, c.x), select8(a.s, a.x, c.x));
  ty = _mm256_sub_ps(select8(b.s, b.y, c.y), select8(a.s, a.y, c.y));
  tz = _mm256_sub_ps(select8(b.s, b.z, c.z), select8(a.s, a.z, c.z));
}

TM_AVX2 inline void load_xyz8(const float* p, __m256& x, __m256& y, __m256& z) {
  __m128 x0, y0, z0, x1, y1, z1;
  load_xyz4(p, x0, y0, z0);
  load_xyz4(p + 12, x1, y1, z1);
  x = _mm256_set_m128(x1, x0), y = _mm256_set_m128(y1, y0), z = _mm256_set_m128(z1, z0);
}

TM_AVX2 inline void store_xyz8(float* p, __m256 x, __m256 y, __m256 z) {
  store_xyz4(p, _mm256_castps256_ps128(x), _mm256_castps256_ps128(y), _mm256_castps256_ps128(z));
  store_xyz4(p + 12, _mm256_extractf128_ps(x, 1), _mm256_extractf128_ps(y, 1), _mm256_extractf128_ps(z, 1));
}

}  // namespace

TM_AVX2 int normals_row_avx2(const MeanRows& m, int r, const std::uint8_t* near_edge, const float* p, float* out,
                             int w) {
  const __m256 nan8 = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
  const __m256 sign = _mm256_set1_ps(-0.0f), zero = _mm256_setzero_ps();
  const int n8 = w & ~7;
  for (int u = 0; u < n8; u += 8) {
    __m256 px, py, pz;
    load_xyz8(p + 3 * u, px, py, pz);
    std::uint64_t near8;
    std::memcpy(&near8, near_edge + u, 8);
    const __m256i near32 = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(near8)));
    const __m256 far_from_edge = _mm256_castsi256_ps(_mm256_cmpeq_epi32(near32, _mm256_setzero_si256()));
    const __m256 wanted = _mm256_and_ps(_mm256_cmp_ps(px, px, _CMP_ORD_Q), far_from_edge);
    float* ou = out + 3 * u;
    if (_mm256_movemask_ps(wanted) == 0) {  // no points or all near edges: common on real frames
      store_xyz8(ou, nan8, nan8, nan8);
      continue;
    }
    const Means8 c = load8(m.mid, u);
    __m256 ux, uy, uz, ok_u, vx, vy, vz, ok_v;
    tangent8(load8(m.mid, u - r), c, load8(m.mid, u + r), ux, uy, uz, ok_u);
    tangent8(load8(m.top, u), c, load8(m.bottom, u), vx, vy, vz, ok_v);
    // n = tv x tu
    const __m256 nx = _mm256_sub_ps(_mm256_mul_ps(vy, uz), _mm256_mul_ps(vz, uy));
    const __m256 ny = _mm256_sub_ps(_mm256_mul_ps(vz, ux), _mm256_mul_ps(vx, uz));
    const __m256 nz = _mm256_sub_ps(_mm256_mul_ps(vx, uy), _mm256_mul_ps(vy, ux));
    const __m256 len2 =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nx, nx), _mm256_mul_ps(ny, ny)), _mm256_mul_ps(nz, nz));
    // 1/|n|: estimate plus one Newton step; its sign turns n towards the camera (n.p < 0).
    const __m256 y0 = _mm256_rsqrt_ps(len2);
    __m256 k = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y0),
                             _mm256_sub_ps(_mm256_set1_ps(3.0f), _mm256_mul_ps(len2, _mm256_mul_ps(y0, y0))));
    const __m256 n_dot_p =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(nx, px), _mm256_mul_ps(ny, py)), _mm256_mul_ps(nz, pz));
    k = _mm256_xor_ps(k, _mm256_and_ps(_mm256_cmp_ps(n_dot_p, zero, _CMP_GT_OQ), sign));
    const __m256 valid = _mm256_and_ps(
        _mm256_and_ps(_mm256_and_ps(ok_u, ok_v), _mm256_cmp_ps(len2, zero, _CMP_GT_OQ)), wanted);
    store_xyz8(ou, select8(valid, _mm256_mul_ps(nx, k), nan8), select8(valid, _mm256_mul_ps(ny, k), nan8),
               select8(valid, _mm256_mul_ps(nz, k), nan8));
  }
  return n8;
}

}  // namespace tunnelmap
