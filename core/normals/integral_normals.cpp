#include "core/normals/integral_normals.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

namespace tunnelmap {

namespace {

// Per-thread scratch, reused across frames (no allocation per frame in the steady state).
// Points and their box means are (x, y, z, support) quadruples, one SSE register per pixel: a
// box sum of the four channels is then one vector addition per step. The float images are
// ring buffers of a few rows, filled and consumed in one streaming pass over the frame, so the
// working set stays in the cache instead of making seven passes over ~5 MB images.
struct Scratch {
  std::vector<float> q_ring;     // quadruples of the last rows (x, y, z, 1; 0 where invalid)
  std::vector<float> mean_ring;  // box means of the last rows (support 1 or 0)
  std::vector<float> inv_ring;   // inverse depth of the last rows, 0 = no measurement
  std::vector<float> acc;        // vertical box sums of the current row (4 per pixel)
  std::vector<std::uint8_t> edges, row_dilated, near_edge;  // full images, one byte per pixel
  std::vector<int> edge_count;
};

// The support lane (w) of a quadruple broadcast as an all-ones / all-zeros mask.
inline __m128 has_support(__m128 q) {
  return _mm_cmpgt_ps(_mm_shuffle_ps(q, q, _MM_SHUFFLE(3, 3, 3, 3)), _mm_setzero_ps());
}
inline __m128 select(__m128 mask, __m128 a, __m128 b) {  // mask ? a : b
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

// Tangent between the box means at a (before) and b (after) the centre c: central where both
// sides have support, else one-sided against the centre, so normals reach up to holes. `ok`
// tells whether any tangent exists.
inline __m128 tangent(__m128 a, __m128 c, __m128 b, bool& ok) {
  const __m128 sa = has_support(a), sb = has_support(b), sc = has_support(c);
  const int fa = _mm_movemask_ps(sa) & 1, fb = _mm_movemask_ps(sb) & 1, fc = _mm_movemask_ps(sc) & 1;
  ok = (fa & fb) | (fc & (fa | fb));
  return _mm_sub_ps(select(sb, b, c), select(sa, a, c));
}

// Unit normal from the row tangent tu and column tangent tv (cross product tv x tu), facing
// the camera from point p (lane 3 ignored); NaN when degenerate. All in registers.
inline __m128 normal_from_tangents(__m128 tu, __m128 tv, __m128 p, bool ok) {
  const __m128 a_yzx = _mm_shuffle_ps(tv, tv, _MM_SHUFFLE(3, 0, 2, 1));
  const __m128 a_zxy = _mm_shuffle_ps(tv, tv, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 b_yzx = _mm_shuffle_ps(tu, tu, _MM_SHUFFLE(3, 0, 2, 1));
  const __m128 b_zxy = _mm_shuffle_ps(tu, tu, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 cr = _mm_sub_ps(_mm_mul_ps(a_yzx, b_zxy), _mm_mul_ps(a_zxy, b_yzx));  // lane 3 = 0
  auto dot3 = [](__m128 x, __m128 y) {  // x.y over lanes 0..2, in lane 0
    const __m128 m = _mm_mul_ps(x, y);
    return _mm_add_ss(_mm_add_ss(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 1, 1, 1))),
                      _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 2, 2, 2)));
  };
  const float len2 = _mm_cvtss_f32(dot3(cr, cr));
  if (!ok || !(len2 > 0.0f)) return _mm_set1_ps(std::numeric_limits<float>::quiet_NaN());
  float k = 1.0f / std::sqrt(len2);
  if (_mm_cvtss_f32(dot3(cr, p)) > 0.0f) k = -k;  // face the camera: n.p < 0
  return _mm_mul_ps(cr, _mm_set1_ps(k));
}

}  // namespace

void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud) {
  StageTimer timer(cloud.timings_ms, "normals");
  const int w = cloud.width, h = cloud.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.normals.resize(n);
  if (w < 3 || h < 3) {
    std::fill(cloud.normals.begin(), cloud.normals.end(), Eigen::Vector3f(nan, nan, nan));
    return;
  }
  const int side = std::max(3, options.smoothing_px);
  const int r = std::max(1, side / 2);          // gradient step between the two box means
  const int r0 = side / 2, r1 = side - 1 - r0;  // box window [x - r0, x + r1]
  const int R = r + side / 2;                   // no box may straddle an edge within R px
  const float limit = static_cast<float>(options.max_depth_change);
  const float min_count = 0.25f * side * side;  // a box with less support has no mean

  // Row i of each stage is produced at step t of the stream, in this order:
  //   ingest (quadruples, inverse depth)  i = t
  //   edges + row dilation                i = t - 1      (needs inverse depth rows i-1..i+1)
  //   box means                           i = t - r1     (needs quadruple rows i-r0-1..i+r1)
  //   near-edge (column dilation)         i = t - 1 - R  (needs dilated rows i-R..i+R)
  //   normals                             i = t - lag    (needs means i-r..i+r, near-edge i)
  const int lag = std::max(r1 + r, 1 + R);
  const int q_rows = side + 2, mean_rows = lag - r1 + r + 2, inv_rows = 4;
  const std::size_t row4 = 4 * static_cast<std::size_t>(w);

  thread_local Scratch s;
  s.q_ring.resize(q_rows * row4);
  s.mean_ring.resize(mean_rows * row4);
  s.inv_ring.resize(inv_rows * static_cast<std::size_t>(w));
  s.acc.resize(row4);
  s.edges.resize(n), s.row_dilated.resize(n), s.near_edge.resize(n);
  s.edge_count.assign(w, 0);
  auto q_row = [&](int i) { return s.q_ring.data() + (i % q_rows) * row4; };
  auto mean_row = [&](int i) { return s.mean_ring.data() + (i % mean_rows) * row4; };
  auto inv_row = [&](int i) { return s.inv_ring.data() + (i % inv_rows) * static_cast<std::size_t>(w); };
  const float* pts = cloud.points.data()->data();
  float* out = cloud.normals.data()->data();

  for (int t = 0; t < h + lag; ++t) {
    if (t < h) {  // ingest
      const float* p = pts + 3 * static_cast<std::size_t>(t) * w;
      float* q = q_row(t);
      float* inv = inv_row(t);
      for (int u = 0; u < w; ++u) {
        const float x = p[3 * u], y = p[3 * u + 1], z = p[3 * u + 2];
        const bool ok = x == x;
        q[4 * u] = ok ? x : 0.0f;
        q[4 * u + 1] = ok ? y : 0.0f;
        q[4 * u + 2] = ok ? z : 0.0f;
        q[4 * u + 3] = ok ? 1.0f : 0.0f;
        inv[u] = ok ? 1.0f / z : 0.0f;
      }
    }
    if (const int e = t - 1; e >= 0 && e < h) {
      // Depth discontinuities from the second difference of inverse depth along rows and
      // columns: inverse depth is linear in the pixel coordinates on ANY plane, so walls seen
      // at grazing angles are not edges (a first difference of depth would be), while real
      // jumps (plate borders, the manhole opening) are.
      std::uint8_t* ed = s.edges.data() + static_cast<std::size_t>(e) * w;
      std::fill(ed, ed + w, 0);
      if (e > 0 && e + 1 < h) {
        const float* up = inv_row(e - 1);
        const float* mid = inv_row(e);
        const float* down = inv_row(e + 1);
        for (int u = 1; u + 1 < w; ++u) {
          const float d = mid[u];
          const float th = limit * d;
          const bool row_edge = (mid[u - 1] > 0) & (mid[u + 1] > 0) & (std::abs(mid[u - 1] - 2 * d + mid[u + 1]) > th);
          const bool col_edge = (up[u] > 0) & (down[u] > 0) & (std::abs(up[u] - 2 * d + down[u]) > th);
          ed[u] = (d > 0) & (row_edge | col_edge);
        }
      }
      // Row dilation: any edge within R columns.
      std::uint8_t* rd = s.row_dilated.data() + static_cast<std::size_t>(e) * w;
      int count = 0;
      for (int u = 0; u < std::min(R, w); ++u) count += ed[u];
      for (int u = 0; u < w; ++u) {
        if (u + R < w) count += ed[u + R];
        if (u - R - 1 >= 0) count -= ed[u - R - 1];
        rd[u] = count > 0;
      }
    }
    if (const int j = t - r1; j >= 0 && j < h) {
      // Vertical box sum of row j into acc (re-anchored every 64 rows so float rounding cannot
      // drift), then the horizontal box sum and the means, into the mean ring.
      float* acc = s.acc.data();
      if ((j & 63) == 0) {
        std::fill(acc, acc + row4, 0.0f);
        for (int k = std::max(0, j - r0); k <= std::min(h - 1, j + r1); ++k) {
          const float* q = q_row(k);
          for (std::size_t x = 0; x < row4; ++x) acc[x] += q[x];
        }
      } else {
        const float* add = j + r1 < h ? q_row(j + r1) : nullptr;
        const float* sub = j - r0 - 1 >= 0 ? q_row(j - r0 - 1) : nullptr;
        if (add && sub)
          for (std::size_t x = 0; x < row4; ++x) acc[x] += add[x] - sub[x];
        else if (add)
          for (std::size_t x = 0; x < row4; ++x) acc[x] += add[x];
        else if (sub)
          for (std::size_t x = 0; x < row4; ++x) acc[x] -= sub[x];
      }
      float* m = mean_row(j);
      const __m128 min_count4 = _mm_set1_ps(min_count), one4 = _mm_set1_ps(1.0f);
      const __m128 lane3 = _mm_castsi128_ps(_mm_set_epi32(-1, 0, 0, 0));
      __m128 sum = _mm_setzero_ps();
      for (int u = 0; u < w; ++u) {
        if ((u & 63) == 0) {
          sum = _mm_setzero_ps();
          for (int k = std::max(0, u - r0); k <= std::min(w - 1, u + r1); ++k) sum = _mm_add_ps(sum, _mm_loadu_ps(acc + 4 * k));
        } else {
          const __m128 in = u + r1 < w ? _mm_loadu_ps(acc + 4 * (u + r1)) : _mm_setzero_ps();
          const __m128 leave = u - r0 - 1 >= 0 ? _mm_loadu_ps(acc + 4 * (u - r0 - 1)) : _mm_setzero_ps();
          sum = _mm_add_ps(sum, _mm_sub_ps(in, leave));
        }
        // Mean = sum / support where the support reaches the minimum; lane 3 becomes 1 or 0.
        const __m128 cnt = _mm_shuffle_ps(sum, sum, _MM_SHUFFLE(3, 3, 3, 3));
        const __m128 ok = _mm_cmpge_ps(cnt, min_count4);
        const __m128 mean = _mm_and_ps(ok, _mm_div_ps(sum, cnt));
        _mm_storeu_ps(m + 4 * u, select(lane3, _mm_and_ps(ok, one4), mean));
      }
    }
    if (const int ne = t - 1 - R; ne >= 0 && ne < h) {
      // Column dilation of the row-dilated edges: near_edge = an edge within R in both directions.
      int* count = s.edge_count.data();
      if (ne == 0)
        for (int k = 0; k < std::min(R, h); ++k) {
          const std::uint8_t* rd = s.row_dilated.data() + static_cast<std::size_t>(k) * w;
          for (int u = 0; u < w; ++u) count[u] += rd[u];
        }
      if (ne + R < h) {
        const std::uint8_t* rd = s.row_dilated.data() + static_cast<std::size_t>(ne + R) * w;
        for (int u = 0; u < w; ++u) count[u] += rd[u];
      }
      if (ne - R - 1 >= 0) {
        const std::uint8_t* rd = s.row_dilated.data() + static_cast<std::size_t>(ne - R - 1) * w;
        for (int u = 0; u < w; ++u) count[u] -= rd[u];
      }
      std::uint8_t* o = s.near_edge.data() + static_cast<std::size_t>(ne) * w;
      for (int u = 0; u < w; ++u) o[u] = count[u] > 0;
    }
    if (const int v = t - lag; v >= 0 && v < h) {
      // A side outside the image reads as "no support": a one-sided tangent (or none).
      const float* mid = mean_row(v);
      const float* top = v - r >= 0 ? mean_row(v - r) : nullptr;
      const float* bottom = v + r < h ? mean_row(v + r) : nullptr;
      const std::uint8_t* near = s.near_edge.data() + static_cast<std::size_t>(v) * w;
      const float* p = pts + 3 * static_cast<std::size_t>(v) * w;
      float* o = out + 3 * static_cast<std::size_t>(v) * w;
      for (int u = 0; u < w; ++u) {
        float* ou = o + 3 * u;
        if (!(p[3 * u] == p[3 * u]) || near[u]) {
          ou[0] = ou[1] = ou[2] = nan;
          continue;
        }
        const __m128 c = _mm_loadu_ps(mid + 4 * u);
        const __m128 a = u - r >= 0 ? _mm_loadu_ps(mid + 4 * (u - r)) : _mm_setzero_ps();
        const __m128 b = u + r < w ? _mm_loadu_ps(mid + 4 * (u + r)) : _mm_setzero_ps();
        const __m128 up = top ? _mm_loadu_ps(top + 4 * u) : _mm_setzero_ps();
        const __m128 down = bottom ? _mm_loadu_ps(bottom + 4 * u) : _mm_setzero_ps();
        bool ok_u, ok_v;
        const __m128 tu = tangent(a, c, b, ok_u);
        const __m128 tv = tangent(up, c, down, ok_v);
        const __m128 point = _mm_setr_ps(p[3 * u], p[3 * u + 1], p[3 * u + 2], 0.0f);
        const __m128 nrm = normal_from_tangents(tu, tv, point, ok_u && ok_v);
        // Three floats out: the 4th lane spills onto the next pixel's x, which is written after
        // (not for the frame's last pixel, which has no next).
        if (v + 1 < h || u + 1 < w) {
          _mm_storeu_ps(ou, nrm);
        } else {
          alignas(16) float f[4];
          _mm_store_ps(f, nrm);
          ou[0] = f[0], ou[1] = f[1], ou[2] = f[2];
        }
      }
    }
  }
}

}  // namespace tunnelmap
