#pragma once
// Four pixels' (x, y, z) triples, stored back to back (12 floats, the layout of an organised
// cloud's points and normals), to and from one SSE vector per coordinate.
#include <xmmintrin.h>

namespace tunnelmap {

inline void load_xyz4(const float* p, __m128& x, __m128& y, __m128& z) {
  const __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4), c = _mm_loadu_ps(p + 8);
  // a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3
  const __m128 bc_x = _mm_shuffle_ps(b, c, _MM_SHUFFLE(0, 1, 0, 2));  // x2 . x3 .
  const __m128 ab_y = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 0, 1));  // y0 . y1 .
  const __m128 bc_y = _mm_shuffle_ps(b, c, _MM_SHUFFLE(0, 2, 0, 3));  // y2 . y3 .
  const __m128 ab_z = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 1, 0, 2));  // z0 . z1 .
  const __m128 cc_z = _mm_shuffle_ps(c, c, _MM_SHUFFLE(0, 3, 0, 0));  // z2 . z3 .
  x = _mm_shuffle_ps(a, bc_x, _MM_SHUFFLE(2, 0, 3, 0));
  y = _mm_shuffle_ps(ab_y, bc_y, _MM_SHUFFLE(2, 0, 2, 0));
  z = _mm_shuffle_ps(ab_z, cc_z, _MM_SHUFFLE(2, 0, 2, 0));
}

inline void store_xyz4(float* p, __m128 x, __m128 y, __m128 z) {
  // x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3
  const __m128 xy_lo = _mm_unpacklo_ps(x, y);  // x0 y0 x1 y1
  const __m128 xy_hi = _mm_unpackhi_ps(x, y);  // x2 y2 x3 y3
  const __m128 a = _mm_shuffle_ps(xy_lo, _mm_shuffle_ps(z, xy_lo, _MM_SHUFFLE(2, 2, 0, 0)),
                                  _MM_SHUFFLE(2, 0, 1, 0));                         // x0 y0 z0 x1
  const __m128 b = _mm_shuffle_ps(_mm_shuffle_ps(xy_lo, z, _MM_SHUFFLE(1, 1, 3, 3)), xy_hi,
                                  _MM_SHUFFLE(1, 0, 2, 0));                         // y1 z1 x2 y2
  const __m128 c = _mm_shuffle_ps(_mm_shuffle_ps(z, xy_hi, _MM_SHUFFLE(2, 2, 2, 2)),
                                  _mm_shuffle_ps(xy_hi, z, _MM_SHUFFLE(3, 3, 3, 1)),
                                  _MM_SHUFFLE(2, 1, 2, 0));                         // z2 x3 y3 z3
  _mm_storeu_ps(p, a), _mm_storeu_ps(p + 4, b), _mm_storeu_ps(p + 8, c);
}

}  // namespace tunnelmap
