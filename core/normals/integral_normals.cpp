#include "core/normals/integral_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Geometry>

namespace tunnelmap {

namespace {

// Scratch planes, one float per pixel each (structure of arrays, so the loops vectorise).
struct Planes {
  std::vector<float> x, y, z, c;  // points (0 where invalid) and the valid flag
  void resize(std::size_t n) {
    x.resize(n), y.resize(n), z.resize(n), c.resize(n);
  }
};

// Box sum over a side-`s` window, separable: rows with running sums (re-anchored every 64 px
// so float rounding cannot drift), then columns with a row of accumulators. The same box sums
// as Holzer's summed-area tables, in float and in cache-friendly passes.
void box_sum(const float* in, int w, int h, int s, float* tmp, float* out, std::vector<float>& acc) {
  const int r0 = s / 2, r1 = s - 1 - r0;  // window [x - r0, x + r1]
  for (int v = 0; v < h; ++v) {
    const float* row = in + static_cast<std::size_t>(v) * w;
    float* dst = tmp + static_cast<std::size_t>(v) * w;
    float sum = 0;
    for (int u = 0; u < w; ++u) {
      if ((u & 63) == 0) {
        sum = 0;
        for (int k = std::max(0, u - r0); k <= std::min(w - 1, u + r1); ++k) sum += row[k];
      } else {
        if (u + r1 < w) sum += row[u + r1];
        if (u - r0 - 1 >= 0) sum -= row[u - r0 - 1];
      }
      dst[u] = sum;
    }
  }
  acc.assign(w, 0.0f);
  float* a = acc.data();
  for (int v = 0; v < h; ++v) {
    if ((v & 63) == 0) {
      std::fill(acc.begin(), acc.end(), 0.0f);
      for (int k = std::max(0, v - r0); k <= std::min(h - 1, v + r1); ++k) {
        const float* src = tmp + static_cast<std::size_t>(k) * w;
        for (int u = 0; u < w; ++u) a[u] += src[u];
      }
    } else {
      if (v + r1 < h) {
        const float* src = tmp + static_cast<std::size_t>(v + r1) * w;
        for (int u = 0; u < w; ++u) a[u] += src[u];
      }
      if (v - r0 - 1 >= 0) {
        const float* src = tmp + static_cast<std::size_t>(v - r0 - 1) * w;
        for (int u = 0; u < w; ++u) a[u] -= src[u];
      }
    }
    std::copy(a, a + w, out + static_cast<std::size_t>(v) * w);
  }
}

// Pixels within `radius` (Chebyshev) of a flagged pixel: separable running counts.
void dilate(const std::vector<std::uint8_t>& flags, int w, int h, int radius, std::vector<std::uint8_t>& out) {
  thread_local std::vector<std::uint16_t> rows;
  rows.resize(flags.size());
  for (int v = 0; v < h; ++v) {
    const std::uint8_t* f = flags.data() + static_cast<std::size_t>(v) * w;
    std::uint16_t* r = rows.data() + static_cast<std::size_t>(v) * w;
    int count = 0;
    for (int u = 0; u < std::min(radius, w); ++u) count += f[u];
    for (int u = 0; u < w; ++u) {
      if (u + radius < w) count += f[u + radius];
      if (u - radius - 1 >= 0) count -= f[u - radius - 1];
      r[u] = static_cast<std::uint16_t>(count);
    }
  }
  out.assign(flags.size(), 0);
  thread_local std::vector<int> count;
  count.assign(w, 0);
  for (int v = 0; v < std::min(radius, h); ++v)
    for (int u = 0; u < w; ++u) count[u] += rows[static_cast<std::size_t>(v) * w + u] > 0;
  for (int v = 0; v < h; ++v) {
    if (v + radius < h)
      for (int u = 0; u < w; ++u) count[u] += rows[static_cast<std::size_t>(v + radius) * w + u] > 0;
    if (v - radius - 1 >= 0)
      for (int u = 0; u < w; ++u) count[u] -= rows[static_cast<std::size_t>(v - radius - 1) * w + u] > 0;
    std::uint8_t* o = out.data() + static_cast<std::size_t>(v) * w;
    for (int u = 0; u < w; ++u) o[u] = count[u] > 0;
  }
}

}  // namespace

void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud) {
  StageTimer timer(cloud.timings_ms, "normals");
  const int w = cloud.width, h = cloud.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.normals.assign(n, Eigen::Vector3f(nan, nan, nan));
  if (w < 3 || h < 3) return;

  // Thread-local scratch: no allocation per frame in the steady state.
  thread_local Planes in, mean;
  thread_local std::vector<float> inv, tmp, acc;
  thread_local std::vector<std::uint8_t> edges, near_edge;
  in.resize(n);
  mean.resize(n);
  inv.resize(n);
  tmp.resize(n);
  edges.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    const bool ok = OrganizedCloud::valid(p);
    in.x[i] = ok ? p.x() : 0.0f;
    in.y[i] = ok ? p.y() : 0.0f;
    in.z[i] = ok ? p.z() : 0.0f;
    in.c[i] = ok ? 1.0f : 0.0f;
    inv[i] = ok ? 1.0f / p.z() : 0.0f;  // inverse depth, 0 = no measurement
  }

  // Depth discontinuities from the second difference of inverse depth along rows and columns:
  // inverse depth is linear in the pixel coordinates on ANY plane, so tilted walls seen at
  // grazing angles do not count as edges (a first difference of depth would), while real jumps
  // (plate borders, the manhole opening) do.
  const float limit = static_cast<float>(options.max_depth_change);
  for (int v = 1; v + 1 < h; ++v) {
    const float* up = inv.data() + static_cast<std::size_t>(v - 1) * w;
    const float* mid = up + w;
    const float* down = mid + w;
    std::uint8_t* e = edges.data() + static_cast<std::size_t>(v) * w;
    for (int u = 1; u + 1 < w; ++u) {
      const float d = mid[u];
      const float t = limit * d;
      const bool row_edge = (mid[u - 1] > 0) & (mid[u + 1] > 0) & (std::abs(mid[u - 1] - 2 * d + mid[u + 1]) > t);
      const bool col_edge = (up[u] > 0) & (down[u] > 0) & (std::abs(up[u] - 2 * d + down[u]) > t);
      e[u] = (d > 0) & (row_edge | col_edge);
    }
  }

  const int s = std::max(3, options.smoothing_px);
  const int r = std::max(1, s / 2);  // gradient step between the two box means
  box_sum(in.x.data(), w, h, s, tmp.data(), mean.x.data(), acc);
  box_sum(in.y.data(), w, h, s, tmp.data(), mean.y.data(), acc);
  box_sum(in.z.data(), w, h, s, tmp.data(), mean.z.data(), acc);
  box_sum(in.c.data(), w, h, s, tmp.data(), mean.c.data(), acc);
  // No box may straddle a discontinuity: drop pixels with an edge within the span of the boxes.
  dilate(edges, w, h, r + s / 2, near_edge);

  // Box sums to means; a box with support below a quarter of the window has no mean (c = 0).
  const float min_count = 0.25f * s * s;
  for (std::size_t i = 0; i < n; ++i) {
    const float cnt = mean.c[i];
    const bool ok = cnt >= min_count;
    const float k = ok ? 1.0f / cnt : 0.0f;
    mean.x[i] *= k, mean.y[i] *= k, mean.z[i] *= k;
    mean.c[i] = ok ? 1.0f : 0.0f;
  }

  const float* mx = mean.x.data();
  const float* my = mean.y.data();
  const float* mz = mean.z.data();
  const float* mc = mean.c.data();
  // Tangent between the means at i - step (a), i (centre) and i + step (b): central where both
  // sides have support, else one-sided against the centre, so normals reach up to holes.
  auto tangent = [&](std::ptrdiff_t i, std::ptrdiff_t a, std::ptrdiff_t b, bool has_a, bool has_b,
                     Eigen::Vector3f& t) {
    has_a = has_a && mc[a] > 0;
    has_b = has_b && mc[b] > 0;
    if (!(has_a && has_b)) {
      if (mc[i] == 0 || (!has_a && !has_b)) return false;
      if (!has_a) a = i;
      if (!has_b) b = i;
    }
    t = Eigen::Vector3f(mx[b] - mx[a], my[b] - my[a], mz[b] - mz[a]);
    return true;
  };

  for (int v = 0; v < h; ++v) {
    const bool has_up = v - r >= 0, has_down = v + r < h;
    for (int u = 0; u < w; ++u) {
      const std::ptrdiff_t i = static_cast<std::ptrdiff_t>(v) * w + u;
      if (in.c[i] == 0 || near_edge[i]) continue;
      Eigen::Vector3f tu, tv;
      if (!tangent(i, i - r, i + r, u - r >= 0, u + r < w, tu)) continue;
      if (!tangent(i, i - static_cast<std::ptrdiff_t>(r) * w, i + static_cast<std::ptrdiff_t>(r) * w, has_up,
                   has_down, tv))
        continue;
      Eigen::Vector3f nrm = tv.cross(tu);
      const float len2 = nrm.squaredNorm();
      if (!(len2 > 0.0f)) continue;
      nrm *= 1.0f / std::sqrt(len2);
      if (nrm.dot(cloud.points[i]) > 0.0f) nrm = -nrm;  // face the camera
      cloud.normals[i] = nrm;
    }
  }
}

}  // namespace tunnelmap
