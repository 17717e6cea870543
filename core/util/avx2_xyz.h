#pragma once
// Eight pixels' (x, y, z) triples (24 floats, an organised cloud's layout) to one AVX vector
// per coordinate, for code compiled with __attribute__((target("avx2"))) and chosen at run time.
#include <immintrin.h>

namespace tunnelmap {

// The lanes hold the points in the order 0 3 6 1 4 7 2 5 (the same in x, y and z): three
// blends gather each coordinate and only y and z need a lane rotation to line up with x.
__attribute__((target("avx2"))) inline void load_xyz8(const float* p, __m256& x, __m256& y, __m256& z) {
  const __m256 a = _mm256_loadu_ps(p), b = _mm256_loadu_ps(p + 8), c = _mm256_loadu_ps(p + 16);
  // x: a lanes 0 3 6, b lanes 1 4 7, c lanes 2 5 -> points 0 3 6 1 4 7 2 5.
  x = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x92), c, 0x24);
  // y: c lanes 0 3 6, a lanes 1 4 7, b lanes 2 5 -> points 5 0 3 6 1 4 7 2.
  const __m256 yr = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x24), c, 0x49);
  // z: b lanes 0 3 6, c lanes 1 4 7, a lanes 2 5 -> points 2 5 0 3 6 1 4 7.
  const __m256 zr = _mm256_blend_ps(_mm256_blend_ps(a, b, 0x49), c, 0x92);
  y = _mm256_permutevar8x32_ps(yr, _mm256_setr_epi32(1, 2, 3, 4, 5, 6, 7, 0));
  z = _mm256_permutevar8x32_ps(zr, _mm256_setr_epi32(2, 3, 4, 5, 6, 7, 0, 1));
}

// Pixel k sits in lane xyz8_pixel_order()[k] after load_xyz8: _mm256_permutevar8x32_* with it
// puts a vector in that lane order back into pixel order.
__attribute__((target("avx2"))) inline __m256i xyz8_pixel_order() {
  return _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
}

}  // namespace tunnelmap
