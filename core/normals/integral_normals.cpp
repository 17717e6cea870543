#include "core/normals/integral_normals.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "core/normals/normals_row_avx2.h"
#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {

inline __m128 select(__m128 mask, __m128 a, __m128 b) {  // mask ? a : b
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

// Box means of four pixels, one vector per channel; `s` is all-ones where a mean exists.
struct Means4 {
  __m128 x, y, z, s;
  static Means4 load(const float* const planes[4], int u) {
    return {_mm_loadu_ps(planes[0] + u), _mm_loadu_ps(planes[1] + u), _mm_loadu_ps(planes[2] + u),
            _mm_cmpgt_ps(_mm_loadu_ps(planes[3] + u), _mm_setzero_ps())};
  }
};

// Tangent between the box means at a (before) and b (after) the centre c, four pixels at once:
// central where both sides have support, else one-sided against the centre, so normals reach
// up to holes. `ok` is all-ones where any tangent exists.
inline void tangent4(const Means4& a, const Means4& c, const Means4& b, __m128& tx, __m128& ty, __m128& tz,
                     __m128& ok) {
  ok = _mm_or_ps(_mm_and_ps(a.s, b.s), _mm_and_ps(c.s, _mm_or_ps(a.s, b.s)));
  tx = _mm_sub_ps(select(b.s, b.x, c.x), select(a.s, a.x, c.x));
  ty = _mm_sub_ps(select(b.s, b.y, c.y), select(a.s, a.y, c.y));
  tz = _mm_sub_ps(select(b.s, b.z, c.z), select(a.s, a.z, c.z));
}

}  // namespace

void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud) {
  NormalScratch scratch;
  estimate_normals(options, cloud, scratch);
}

void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud, NormalScratch& s) {
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
  // Mean rows are stored as four channel planes (x, y, z, support) so that the normals stage
  // loads four pixels' channels with one instruction each. Each plane has `mpad` zero pixels
  // (no support) on both sides: the gradient's neighbours at u +- r need no bounds tests.
  const int w4 = (w + 3) & ~3;
  const int mpad = (r + 3) & ~3;
  const std::size_t mplane = static_cast<std::size_t>(w4 + 2 * mpad), mrow = 4 * mplane;

  s.q_ring.resize(q_rows * row4);
  s.mean_ring.assign(mean_rows * mrow, 0.0f);  // the pads stay zero: only [0, w) is written
  s.mean_aos.assign(4 * static_cast<std::size_t>(w4), 0.0f);
  s.no_means.assign(mrow, 0.0f);
  s.inv_ring.resize(inv_rows * static_cast<std::size_t>(w));
  s.acc.resize(row4);
  s.edges.resize(n), s.row_dilated.resize(n), s.near_edge.resize(n);
  s.edge_count.assign(w, 0);
  auto q_row = [&](int i) { return s.q_ring.data() + (i % q_rows) * row4; };
  // Channel plane c of mean row i, at pixel 0.
  auto mean_plane = [&](int i, int c) { return s.mean_ring.data() + (i % mean_rows) * mrow + c * mplane + mpad; };
  auto inv_row = [&](int i) { return s.inv_ring.data() + (i % inv_rows) * static_cast<std::size_t>(w); };
  const float* pts = cloud.points.data()->data();
  float* out = cloud.normals.data()->data();

  // Normals of row v, four pixels at a time: the cross product of the column and row tangents,
  // unit length, facing the camera; NaN without a point, near an edge or without tangents.
  const bool avx2 = normals_avx2_available();
  const auto normals_row = [&](int v) {
    const float* mid[4];
    const float* top[4];
    const float* bottom[4];
    for (int c = 0; c < 4; ++c) {
      mid[c] = mean_plane(v, c);
      top[c] = v - r >= 0 ? mean_plane(v - r, c) : s.no_means.data() + c * mplane + mpad;
      bottom[c] = v + r < h ? mean_plane(v + r, c) : s.no_means.data() + c * mplane + mpad;
    }
    const std::uint8_t* near_row = s.near_edge.data() + static_cast<std::size_t>(v) * w;
    const float* p = pts + 3 * static_cast<std::size_t>(v) * w;
    float* o = out + 3 * static_cast<std::size_t>(v) * w;
    const __m128 nan4 = _mm_set1_ps(std::numeric_limits<float>::quiet_NaN());
    const __m128 sign = _mm_set1_ps(-0.0f), zero = _mm_setzero_ps();
    // Eight pixels at a time where the CPU has AVX2 (the same normals), the rest four at a time.
    const int u_first = avx2 ? normals_row_avx2(MeanRows{{mid[0], mid[1], mid[2], mid[3]},
                                                         {top[0], top[1], top[2], top[3]},
                                                         {bottom[0], bottom[1], bottom[2], bottom[3]}},
                                                r, near_row, p, o, w)
                             : 0;
    for (int u = u_first; u < w; u += 4) {
      const int lanes = std::min(4, w - u);
      __m128 px, py, pz;
      std::uint32_t near4 = 0x01010101u;  // missing lanes count as near an edge
      if (lanes == 4) {
        load_xyz4(p + 3 * u, px, py, pz);
        std::memcpy(&near4, near_row + u, 4);
      } else {
        float tail[12];
        std::fill(tail, tail + 12, std::numeric_limits<float>::quiet_NaN());
        std::copy(p + 3 * u, p + 3 * (u + lanes), tail);
        load_xyz4(tail, px, py, pz);
        std::memcpy(&near4, near_row + u, lanes);
      }
      const __m128i near_bytes = _mm_cvtsi32_si128(static_cast<int>(near4));
      const __m128i near32 = _mm_unpacklo_epi16(_mm_unpacklo_epi8(near_bytes, _mm_setzero_si128()), _mm_setzero_si128());
      const __m128 far_from_edge = _mm_castsi128_ps(_mm_cmpeq_epi32(near32, _mm_setzero_si128()));
      const __m128 wanted = _mm_and_ps(_mm_cmpord_ps(px, px), far_from_edge);
      float* ou = o + 3 * u;
      const auto store = [&](__m128 x, __m128 y, __m128 z) {
        if (lanes == 4) {
          store_xyz4(ou, x, y, z);
        } else {
          float tail[12];
          store_xyz4(tail, x, y, z);
          std::copy(tail, tail + 3 * lanes, ou);
        }
      };
      if (_mm_movemask_ps(wanted) == 0) {  // no points or all near edges: common on real frames
        store(nan4, nan4, nan4);
        continue;
      }

      const Means4 c = Means4::load(mid, u);
      __m128 ux, uy, uz, ok_u, vx, vy, vz, ok_v;
      tangent4(Means4::load(mid, u - r), c, Means4::load(mid, u + r), ux, uy, uz, ok_u);
      tangent4(Means4::load(top, u), c, Means4::load(bottom, u), vx, vy, vz, ok_v);
      // n = tv x tu
      const __m128 nx = _mm_sub_ps(_mm_mul_ps(vy, uz), _mm_mul_ps(vz, uy));
      const __m128 ny = _mm_sub_ps(_mm_mul_ps(vz, ux), _mm_mul_ps(vx, uz));
      const __m128 nz = _mm_sub_ps(_mm_mul_ps(vx, uy), _mm_mul_ps(vy, ux));
      const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, nx), _mm_mul_ps(ny, ny)), _mm_mul_ps(nz, nz));
      // 1/|n| by the estimate plus one Newton step (relative error ~1e-7, no divide latency);
      // its sign turns n towards the camera (n.p < 0).
      const __m128 y0 = _mm_rsqrt_ps(len2);
      __m128 k = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), y0),
                            _mm_sub_ps(_mm_set1_ps(3.0f), _mm_mul_ps(len2, _mm_mul_ps(y0, y0))));
      const __m128 n_dot_p = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, px), _mm_mul_ps(ny, py)), _mm_mul_ps(nz, pz));
      k = _mm_xor_ps(k, _mm_and_ps(_mm_cmpgt_ps(n_dot_p, zero), sign));
      const __m128 valid = _mm_and_ps(_mm_and_ps(_mm_and_ps(ok_u, ok_v), _mm_cmpgt_ps(len2, zero)), wanted);
      const __m128 rx = select(valid, _mm_mul_ps(nx, k), nan4);
      const __m128 ry = select(valid, _mm_mul_ps(ny, k), nan4);
      const __m128 rz = select(valid, _mm_mul_ps(nz, k), nan4);
      store(rx, ry, rz);
    }
  };

  for (int t = 0; t < h + lag; ++t) {
    if (t < h) {  // ingest
      const float* p = pts + 3 * static_cast<std::size_t>(t) * w;
      float* q = q_row(t);
      float* inv = inv_row(t);
      int u = 0;
      // Four pixels at a time: xyz triples to x, y, z vectors, one divide for four inverse
      // depths, then back to (x, y, z, support) quadruples by a 4x4 transpose.
      for (; u + 4 <= w; u += 4) {
        const float* pu = p + 3 * u;
        __m128 x, y, z;
        load_xyz4(pu, x, y, z);
        const __m128 ok = _mm_cmpord_ps(x, x);
        x = _mm_and_ps(ok, x), y = _mm_and_ps(ok, y), z = _mm_and_ps(ok, z);
        __m128 wv = _mm_and_ps(ok, _mm_set1_ps(1.0f));
        _mm_storeu_ps(inv + u, _mm_and_ps(ok, _mm_div_ps(_mm_set1_ps(1.0f), z)));
        _MM_TRANSPOSE4_PS(x, y, z, wv);
        _mm_storeu_ps(q + 4 * u, x);
        _mm_storeu_ps(q + 4 * u + 4, y);
        _mm_storeu_ps(q + 4 * u + 8, z);
        _mm_storeu_ps(q + 4 * u + 12, wv);
      }
      for (; u < w; ++u) {
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
      // The horizontal box sums (a serial chain of additions, one pixel after the other) are
      // stored as they are; the means are taken after the transpose, four pixels per step.
      float* m = s.mean_aos.data();
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
        _mm_storeu_ps(m + 4 * u, sum);
      }
      // Quadruples to channel planes, four pixels at a time (the tail of mean_aos is zero),
      // then mean = sum / support where the support reaches the minimum; support becomes 1 or 0.
      float* mx = mean_plane(j, 0);
      float* my = mean_plane(j, 1);
      float* mz = mean_plane(j, 2);
      float* ms = mean_plane(j, 3);
      const __m128 min_count4 = _mm_set1_ps(min_count), one4 = _mm_set1_ps(1.0f), two4 = _mm_set1_ps(2.0f);
      for (int u = 0; u < w4; u += 4) {
        __m128 q0 = _mm_loadu_ps(m + 4 * u), q1 = _mm_loadu_ps(m + 4 * u + 4);
        __m128 q2 = _mm_loadu_ps(m + 4 * u + 8), q3 = _mm_loadu_ps(m + 4 * u + 12);
        _MM_TRANSPOSE4_PS(q0, q1, q2, q3);
        const __m128 ok = _mm_cmpge_ps(q3, min_count4);
        __m128 rcp = _mm_rcp_ps(q3);  // 1/count: estimate + one Newton step, no divide latency
        rcp = _mm_mul_ps(rcp, _mm_sub_ps(two4, _mm_mul_ps(q3, rcp)));
        _mm_storeu_ps(mx + u, _mm_and_ps(ok, _mm_mul_ps(q0, rcp)));
        _mm_storeu_ps(my + u, _mm_and_ps(ok, _mm_mul_ps(q1, rcp)));
        _mm_storeu_ps(mz + u, _mm_and_ps(ok, _mm_mul_ps(q2, rcp)));
        _mm_storeu_ps(ms + u, _mm_and_ps(ok, one4));
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
    if (const int v = t - lag; v >= 0 && v < h) normals_row(v);
  }
}

}  // namespace tunnelmap
