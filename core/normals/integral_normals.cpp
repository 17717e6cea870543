#include "core/normals/integral_normals.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace tunnelmap {

namespace {

// Box sums over a side-`s` window of 5 channels (x, y, z, valid count, edge count), computed
// as a separable running sum: the same box means as Holzer's summed-area tables, but the
// running sums stay small, so float storage keeps sub-millimetre precision.
struct BoxSums {
  int w = 0, h = 0;
  std::vector<float> data;  // 5 floats per pixel
  const float* at(int u, int v) const {
    static const float kEmpty[5] = {0, 0, 0, 0, 0};  // outside the image: no support
    if (u < 0 || v < 0 || u >= w || v >= h) return kEmpty;
    return data.data() + (static_cast<std::size_t>(v) * w + u) * 5;
  }
};

void box_filter(const std::vector<float>& in, int w, int h, int s, std::vector<float>& tmp,
                BoxSums& out) {
  const int r0 = s / 2, r1 = s - 1 - r0;  // window [u - r0, u + r1]
  tmp.assign(in.size(), 0.0f);
  for (int v = 0; v < h; ++v) {
    const float* row = in.data() + static_cast<std::size_t>(v) * w * 5;
    float* dst = tmp.data() + static_cast<std::size_t>(v) * w * 5;
    double acc[5] = {0, 0, 0, 0, 0};
    for (int u = 0; u < std::min(r1, w); ++u)
      for (int c = 0; c < 5; ++c) acc[c] += row[u * 5 + c];
    for (int u = 0; u < w; ++u) {
      const int add = u + r1, sub = u - r0 - 1;
      if (add < w)
        for (int c = 0; c < 5; ++c) acc[c] += row[add * 5 + c];
      if (sub >= 0)
        for (int c = 0; c < 5; ++c) acc[c] -= row[sub * 5 + c];
      for (int c = 0; c < 5; ++c) dst[u * 5 + c] = static_cast<float>(acc[c]);
    }
  }
  out.w = w;
  out.h = h;
  out.data.assign(in.size(), 0.0f);
  std::vector<double> acc(static_cast<std::size_t>(w) * 5, 0.0);
  const std::size_t stride = static_cast<std::size_t>(w) * 5;
  for (int v = 0; v < std::min(r1, h); ++v)
    for (std::size_t i = 0; i < stride; ++i) acc[i] += tmp[v * stride + i];
  for (int v = 0; v < h; ++v) {
    const int add = v + r1, sub = v - r0 - 1;
    if (add < h)
      for (std::size_t i = 0; i < stride; ++i) acc[i] += tmp[add * stride + i];
    if (sub >= 0)
      for (std::size_t i = 0; i < stride; ++i) acc[i] -= tmp[sub * stride + i];
    float* dst = out.data.data() + v * stride;
    for (std::size_t i = 0; i < stride; ++i) dst[i] = static_cast<float>(acc[i]);
  }
}

Eigen::Vector3f box_mean(const float* b) { return Eigen::Vector3f(b[0], b[1], b[2]) / b[3]; }

// Tangent from the box means before (a), at (c) and after (b) the pixel.
bool gradient(const float* a, const float* c, const float* b, float min_count, Eigen::Vector3f& t) {
  const bool has_a = a[3] >= min_count, has_b = b[3] >= min_count;
  if (has_a && has_b) {
    t = box_mean(b) - box_mean(a);
    return true;
  }
  if (c[3] < min_count) return false;
  if (has_b) {
    t = box_mean(b) - box_mean(c);
    return true;
  }
  if (has_a) {
    t = box_mean(c) - box_mean(a);
    return true;
  }
  return false;
}

}  // namespace

void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud) {
  StageTimer timer(cloud.timings_ms, "normals");
  const int w = cloud.width, h = cloud.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.normals.assign(n, Eigen::Vector3f(nan, nan, nan));
  if (w < 3 || h < 3) return;

  const float jump = static_cast<float>(options.max_depth_change);
  // Channels: point (x, y, z), valid flag, and a depth-discontinuity flag (a jump to the right
  // or lower neighbour larger than max_depth_change * depth, or a valid/invalid border).
  std::vector<float> channels(n * 5, 0.0f);
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const std::size_t i = cloud.index(u, v);
      const Eigen::Vector3f& p = cloud.points[i];
      float* c = channels.data() + i * 5;
      if (!OrganizedCloud::valid(p)) continue;
      c[0] = p.x();
      c[1] = p.y();
      c[2] = p.z();
      c[3] = 1.0f;
      const float limit = jump * p.z();
      if (u + 1 < w) {
        const Eigen::Vector3f& q = cloud.points[i + 1];
        if (OrganizedCloud::valid(q) && std::abs(q.z() - p.z()) > limit) c[4] = 1.0f;
      }
      if (v + 1 < h) {
        const Eigen::Vector3f& q = cloud.points[i + w];
        if (OrganizedCloud::valid(q) && std::abs(q.z() - p.z()) > limit) c[4] = 1.0f;
      }
    }
  }

  const int s = std::max(3, options.smoothing_px);
  const int r = std::max(1, s / 2);  // gradient step between the two box means
  std::vector<float> tmp;
  BoxSums box;
  box_filter(channels, w, h, s, tmp, box);
  // Edge counts over the whole span the two boxes cover (2s), so that no box straddles a
  // depth discontinuity: one more box filter of the edge channel with a side-2s window.
  BoxSums span;
  box_filter(channels, w, h, 2 * s + 1, tmp, span);

  const float min_count = 0.25f * s * s;  // a box mean needs a quarter of its pixels
  for (int v = 0; v < h; ++v) {
    for (int u = 0; u < w; ++u) {
      const std::size_t i = cloud.index(u, v);
      const Eigen::Vector3f& p = cloud.points[i];
      if (!OrganizedCloud::valid(p)) continue;
      if (span.at(u, v)[4] > 0.5f) continue;
      // Central difference of the box means; one-sided (against the centre box) where one
      // side lacks support, so that normals reach up to holes and the image border.
      Eigen::Vector3f tu, tv;
      if (!gradient(box.at(u - r, v), box.at(u, v), box.at(u + r, v), min_count, tu)) continue;
      if (!gradient(box.at(u, v - r), box.at(u, v), box.at(u, v + r), min_count, tv)) continue;
      Eigen::Vector3f nrm = tv.cross(tu);
      const float len = nrm.norm();
      if (!(len > 0.0f)) continue;
      nrm /= len;
      if (nrm.dot(p) > 0.0f) nrm = -nrm;  // face the camera
      cloud.normals[i] = nrm;
    }
  }
}

}  // namespace tunnelmap
