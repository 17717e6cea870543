#include "core/normals/cloud_builder.h"

#include <cmath>
#include <limits>

#include "core/normals/cloud_builder_avx2.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud) {
  CloudScratch scratch;
  build_cloud(frame, options, cloud, scratch);
}

void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud,
                 CloudScratch& scratch) {
  const int w = frame.width, h = frame.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  cloud.width = w;
  cloud.height = h;
  cloud.intrinsics = frame.intrinsics;
  cloud.points.resize(n);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Divided, not multiplied by the reciprocal: a correctly rounded quotient is the same float
  // for 1234 mm and for 6170 units of 1/5000 m (TUM), so one scene in two file layouts gives
  // one cloud, bit for bit. (The reciprocal of 5000 and of 1000 round differently.)
  const float units = static_cast<float>(frame.depth_units_per_m);
  const float zmin = static_cast<float>(options.min_range_m);
  const float zmax = static_cast<float>(options.max_range_m);
  // Precomputed per-column / per-row ray factors: x = (u - cx) / fx * z.
  std::vector<float>& kx = scratch.kx;
  std::vector<float>& ky = scratch.ky;
  kx.resize(w), ky.resize(h);
  for (int u = 0; u < w; ++u) kx[u] = static_cast<float>((u - frame.intrinsics.cx) / frame.intrinsics.fx);
  for (int v = 0; v < h; ++v) ky[v] = static_cast<float>((v - frame.intrinsics.cy) / frame.intrinsics.fy);
  const __m128 units4 = _mm_set1_ps(units), zmin4 = _mm_set1_ps(zmin), zmax4 = _mm_set1_ps(zmax);
  const __m128 nan4 = _mm_set1_ps(nan), zero4 = _mm_setzero_ps();
  const bool avx2 = cloud_builder_avx2_available();
  for (int v = 0; v < h; ++v) {
    const float* d = frame.depth.data() + static_cast<std::size_t>(v) * w;
    float* p = cloud.points.data()->data() + 3 * static_cast<std::size_t>(v) * w;
    const __m128 ky4 = _mm_set1_ps(ky[v]);
    int u = avx2 ? build_cloud_row_avx2(d, kx.data(), ky[v], w, units, zmin, zmax, p) : 0;
    // Four pixels at a time, without a branch on the (often scattered) dropouts. The range
    // test also rejects 0, NaN and inf (ordered comparisons with NaN are false).
    for (; u + 4 <= w; u += 4) {
      const __m128 z = _mm_div_ps(_mm_loadu_ps(d + u), units4);
      const __m128 ok = _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(z, zmin4), _mm_cmple_ps(z, zmax4)), _mm_cmpgt_ps(z, zero4));
      const auto valid_or_nan = [&](__m128 c) { return _mm_or_ps(_mm_and_ps(ok, c), _mm_andnot_ps(ok, nan4)); };
      store_xyz4(p + 3 * u, valid_or_nan(_mm_mul_ps(_mm_loadu_ps(kx.data() + u), z)),
                 valid_or_nan(_mm_mul_ps(ky4, z)), valid_or_nan(z));
    }
    for (; u < w; ++u) {
      const float z = d[u] / units;
      const bool ok = z >= zmin && z <= zmax && z > 0.0f;
      p[3 * u] = ok ? kx[u] * z : nan;
      p[3 * u + 1] = ok ? ky[v] * z : nan;
      p[3 * u + 2] = ok ? z : nan;
    }
  }
}

}  // namespace tunnelmap
