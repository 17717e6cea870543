#include "core/normals/cloud_builder_avx2.h"

#include <immintrin.h>

#include <limits>

#include "core/util/avx2_dispatch.h"
#include "core/util/avx2_xyz.h"

namespace tunnelmap {

namespace {
Avx2Dispatch dispatch;
}  // namespace

bool cloud_builder_avx2_available() { return dispatch.use_avx2(); }
void force_sse_cloud_builder(bool on) { dispatch.force_sse(on); }

__attribute__((target("avx2"))) int build_cloud_row_avx2(const float* depth, const float* kx, float ky, int w,
                                                          float units, float zmin, float zmax, float* points) {
  const __m256 units8 = _mm256_set1_ps(units), zmin8 = _mm256_set1_ps(zmin), zmax8 = _mm256_set1_ps(zmax);
  const __m256 nan8 = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN()), zero8 = _mm256_setzero_ps();
  const __m256 ky8 = _mm256_set1_ps(ky);
  // Computed in load_xyz8's lane order (points 0 3 6 1 4 7 2 5), so that the stores are three
  // blends of x with y and z rotated by one and two lanes (the inverse of load_xyz8).
  const __m256i order = xyz8_pixel_order();
  const __m256i rotate_y = _mm256_setr_epi32(7, 0, 1, 2, 3, 4, 5, 6);
  const __m256i rotate_z = _mm256_setr_epi32(6, 7, 0, 1, 2, 3, 4, 5);
  int u = 0;
  for (; u + 8 <= w; u += 8) {
    const __m256 z = _mm256_div_ps(_mm256_permutevar8x32_ps(_mm256_loadu_ps(depth + u), order), units8);
    const __m256 in_range = _mm256_and_ps(_mm256_cmp_ps(z, zmin8, _CMP_GE_OQ), _mm256_cmp_ps(z, zmax8, _CMP_LE_OQ));
    const __m256 ok = _mm256_and_ps(in_range, _mm256_cmp_ps(z, zero8, _CMP_GT_OQ));
    const __m256 kx8 = _mm256_permutevar8x32_ps(_mm256_loadu_ps(kx + u), order);
    const __m256 x = _mm256_blendv_ps(nan8, _mm256_mul_ps(kx8, z), ok);
    const __m256 y = _mm256_blendv_ps(nan8, _mm256_mul_ps(ky8, z), ok);
    const __m256 zz = _mm256_blendv_ps(nan8, z, ok);
    const __m256 yr = _mm256_permutevar8x32_ps(y, rotate_y), zr = _mm256_permutevar8x32_ps(zz, rotate_z);
    float* p = points + 3 * u;
    _mm256_storeu_ps(p, _mm256_blend_ps(_mm256_blend_ps(x, yr, 0x92), zr, 0x24));
    _mm256_storeu_ps(p + 8, _mm256_blend_ps(_mm256_blend_ps(x, yr, 0x24), zr, 0x49));
    _mm256_storeu_ps(p + 16, _mm256_blend_ps(_mm256_blend_ps(x, yr, 0x49), zr, 0x92));
  }
  return u;
}

}  // namespace tunnelmap
