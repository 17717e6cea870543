#include "core/normals/integral_normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Geometry>

namespace tunnelmap {

namespace {

// Separable box sum of 4 float channels (x, y, z, valid) over a side-`s` window. Running sums
// are re-anchored every 64 pixels so float rounding cannot drift: same box means as Holzer's
// summed-area tables, but in float and in two cache-friendly passes.
void box_sum4(const std::vector<float>& in, int w, int h, int s, std::vector<float>& tmp,
              std::vector<float>& out) {
  const int r0 = s / 2, r1 = s - 1 - r0;  // window [x - r0, x + r1]
  tmp.resize(in.size());
  out.resize(in.size());
  // Rows.
  for (int v = 0; v < h; ++v) {
    const float* row = in.data() + static_cast<std::size_t>(v) * w * 4;
    float* dst = tmp.data() + static_cast<std::size_t>(v) * w * 4;
    float acc[4] = {0, 0, 0, 0};
    for (int u = 0; u < w; ++u) {
      if ((u & 63) == 0) {  // re-anchor: exact sum of the window
        acc[0] = acc[1] = acc[2] = acc[3] = 0;
        for (int k = std::max(0, u - r0); k <= std::min(w - 1, u + r1); ++k)
          for (int c = 0; c < 4; ++c) acc[c] += row[k * 4 + c];
      } else {
        const int add = u + r1, sub = u - r0 - 1;
        if (add < w)
          for (int c = 0; c < 4; ++c) acc[c] += row[add * 4 + c];
        if (sub >= 0)
          for (int c = 0; c < 4; ++c) acc[c] -= row[sub * 4 + c];
      }
      for (int c = 0; c < 4; ++c) dst[u * 4 + c] = acc[c];
    }
  }
  // Columns: a whole row of accumulators at once (vectorises, streams memory).
  const std::size_t stride = static_cast<std::size_t>(w) * 4;
  std::vector<float> acc(stride, 0.0f);
  for (int v = 0; v < h; ++v) {
    float* dst = out.data() + v * stride;
    if ((v & 63) == 0) {
      std::fill(acc.begin(), acc.end(), 0.0f);
      for (int k = std::max(0, v - r0); k <= std::min(h - 1, v + r1); ++k) {
        const float* src = tmp.data() + k * stride;
        for (std::size_t i = 0; i < stride; ++i) acc[i] += src[i];
      }
    } else {
      const int add = v + r1, sub = v - r0 - 1;
      if (add < h) {
        const float* src = tmp.data() + add * stride;
        for (std::size_t i = 0; i < stride; ++i) acc[i] += src[i];
      }
      if (sub >= 0) {
        const float* src = tmp.data() + sub * stride;
        for (std::size_t i = 0; i < stride; ++i) acc[i] -= src[i];
      }
    }
    std::copy(acc.begin(), acc.end(), dst);
  }
}

// Pixels within `radius` (Chebyshev) of a flagged pixel: separable max filter via running counts.
void dilate(const std::vector<std::uint8_t>& flags, int w, int h, int radius, std::vector<std::uint8_t>& out) {
  std::vector<std::uint16_t> rows(flags.size());
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
  std::vector<int> count(w, 0);
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
  thread_local std::vector<float> channels, tmp, sums;
  thread_local std::vector<std::uint8_t> edges, near_edge;
  channels.assign(n * 4, 0.0f);
  edges.assign(n, 0);
  // Depth discontinuities from the second difference of inverse depth along rows and columns:
  // inverse depth is linear in the pixel coordinates on ANY plane, so tilted walls seen at
  // grazing angles do not count as edges (a first difference of depth would), while real jumps
  // (plate borders, the manhole opening) do.
  const float limit = static_cast<float>(options.max_depth_change);
  thread_local std::vector<float> inv;  // inverse depth, 0 = no measurement
  inv.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    const bool ok = OrganizedCloud::valid(p);
    inv[i] = ok ? 1.0f / p.z() : 0.0f;
    if (ok) {
      float* c = channels.data() + i * 4;
      c[0] = p.x(), c[1] = p.y(), c[2] = p.z(), c[3] = 1.0f;
    }
  }
  for (int v = 1; v + 1 < h; ++v) {
    const float* up = inv.data() + static_cast<std::size_t>(v - 1) * w;
    const float* mid = up + w;
    const float* down = mid + w;
    std::uint8_t* e = edges.data() + static_cast<std::size_t>(v) * w;
    for (int u = 1; u + 1 < w; ++u) {
      const float d = mid[u];
      if (d == 0.0f) continue;
      const float t = limit * d;
      const bool row_edge = mid[u - 1] > 0 && mid[u + 1] > 0 && std::abs(mid[u - 1] - 2 * d + mid[u + 1]) > t;
      const bool col_edge = up[u] > 0 && down[u] > 0 && std::abs(up[u] - 2 * d + down[u]) > t;
      e[u] = row_edge || col_edge;
    }
  }

  const int s = std::max(3, options.smoothing_px);
  const int r = std::max(1, s / 2);  // gradient step between the two box means
  box_sum4(channels, w, h, s, tmp, sums);
  // No box may straddle a discontinuity: drop pixels with an edge within the span of the boxes.
  dilate(edges, w, h, r + s / 2, near_edge);

  // Box means in place; support below a quarter of the window = no mean (w channel 0).
  const float min_count = 0.25f * s * s;
  for (std::size_t i = 0; i < n; ++i) {
    float* b = sums.data() + i * 4;
    if (b[3] >= min_count) {
      const float inv = 1.0f / b[3];
      b[0] *= inv, b[1] *= inv, b[2] *= inv, b[3] = 1.0f;
    } else {
      b[3] = 0.0f;
    }
  }
  auto mean = [&](int u, int v) -> const float* {
    static const float kNone[4] = {0, 0, 0, 0};
    if (u < 0 || v < 0 || u >= w || v >= h) return kNone;
    return sums.data() + (static_cast<std::size_t>(v) * w + u) * 4;
  };
  // Tangent from the means before (a), at (c) and after (b) the pixel: central difference, or
  // one-sided where one side lacks support, so normals reach up to holes and the border.
  auto tangent = [](const float* a, const float* c, const float* b, Eigen::Vector3f& t) {
    const float* lo = a[3] > 0 ? a : c;
    const float* hi = b[3] > 0 ? b : c;
    if (lo == hi || lo[3] == 0 || hi[3] == 0) return false;
    t = Eigen::Vector3f(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    return true;
  };

  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const Eigen::Vector3f& p = cloud.points[i];
      if (!OrganizedCloud::valid(p) || near_edge[i]) continue;
      const float* c = mean(u, v);
      Eigen::Vector3f tu, tv;
      if (!tangent(mean(u - r, v), c, mean(u + r, v), tu)) continue;
      if (!tangent(mean(u, v - r), c, mean(u, v + r), tv)) continue;
      Eigen::Vector3f nrm = tv.cross(tu);
      const float len2 = nrm.squaredNorm();
      if (!(len2 > 0.0f)) continue;
      nrm *= 1.0f / std::sqrt(len2);
      if (nrm.dot(p) > 0.0f) nrm = -nrm;  // face the camera
      cloud.normals[i] = nrm;
    }
  }
}

}  // namespace tunnelmap
