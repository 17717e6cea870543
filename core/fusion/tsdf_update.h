#pragma once
// The projective TSDF update of one voxel, shared by the dense and the sparse volume so that
// both fuse with exactly the same weighting, truncation and colour rule.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/frame/depth_frame.h"

namespace tunnelmap {

struct TsdfOptions {
  double truncation_m = 0.03;
  double min_depth_m = 0.3;
  double max_depth_m = 2.5;
  int max_weight = 64;
  std::size_t max_bytes = std::size_t(1800) << 20;  // the dense volume's budget
  int threads = 0;  // 0 = hardware concurrency (at most 8)
};

// One frame's camera model and limits in the float form the voxel loops use.
struct FrameProjection {
  float fx = 0, fy = 0, cx = 0, cy = 0;
  int width = 0, height = 0;
  float units_per_m = 1000.0f;
  float m_per_unit = 0.001f;  // a multiplication per voxel instead of a division
  float trunc = 0.03f, inv_trunc = 1.0f / 0.03f;
  float dmin = 0.3f, dmax = 2.5f;
  std::uint16_t wmax = 64;
  const float* depth = nullptr;
  const std::uint8_t* rgb = nullptr;  // null when the frame has no colour

  FrameProjection(const DepthFrame& frame, const TsdfOptions& o)
      : fx(float(frame.intrinsics.fx)), fy(float(frame.intrinsics.fy)),
        cx(float(frame.intrinsics.cx)), cy(float(frame.intrinsics.cy)), width(frame.width),
        height(frame.height), units_per_m(float(frame.depth_units_per_m)),
        m_per_unit(float(1.0 / frame.depth_units_per_m)),
        trunc(float(o.truncation_m)), inv_trunc(1.0f / float(o.truncation_m)),
        dmin(float(o.min_depth_m)), dmax(float(o.max_depth_m)),
        wmax(static_cast<std::uint16_t>(std::clamp(o.max_weight, 1, 65535))),
        depth(frame.depth.data()), rgb(frame.has_rgb() ? frame.rgb.data() : nullptr) {}
};

// Fuses the observation of the voxel at camera-frame position `pc` (its nearest pixel's depth)
// into its running averages. Voxels hidden more than one truncation behind the surface stay
// as they are (unknown).
inline void update_voxel(const FrameProjection& f, const Eigen::Vector3f& pc, float& tsdf,
                         std::uint16_t& weight, std::uint8_t* rgb, std::uint8_t& color_weight) {
  if (pc.z() < f.dmin) return;
  const float iz = 1.0f / pc.z();
  const float xn = pc.x() * iz, yn = pc.y() * iz;
  const float uf = f.fx * xn + f.cx + 0.5f, vf = f.fy * yn + f.cy + 0.5f;
  if (!(uf >= 0.0f && vf >= 0.0f && uf < float(f.width) && vf < float(f.height))) return;
  const int u = static_cast<int>(uf), v = static_cast<int>(vf);  // nearest pixel
  const std::size_t pix = static_cast<std::size_t>(v) * f.width + u;
  const float d = f.depth[pix] * f.m_per_unit;
  if (!(d >= f.dmin && d <= f.dmax)) return;  // also rejects NaN and 0
  // Distance along the viewing ray (not along z): the ray is sqrt(1+xn^2+yn^2) longer.
  const float sdf = (d - pc.z()) * std::sqrt(1.0f + xn * xn + yn * yn);
  if (sdf < -f.trunc) return;  // hidden behind the surface: unknown, leave it
  const float t = std::min(1.0f, sdf * f.inv_trunc);
  const float wf = float(weight);
  tsdf = (tsdf * wf + t) / (wf + 1.0f);
  if (f.rgb && sdf < f.trunc) {
    // Own weight: free-space observations must not darken the surface colour.
    const std::uint8_t* c = &f.rgb[pix * 3];
    const float cw = float(color_weight);
    const float inv = 1.0f / (cw + 1.0f);
    // Rounded by adding a half (the values are not negative): std::lround is a library call
    // on the baseline x86-64 target, three per surface voxel.
    for (int k = 0; k < 3; ++k) rgb[k] = static_cast<std::uint8_t>((rgb[k] * cw + c[k]) * inv + 0.5f);
    if (color_weight < std::min<int>(f.wmax, 255)) ++color_weight;
  }
  weight = std::min<std::uint16_t>(static_cast<std::uint16_t>(weight + 1), f.wmax);
}

}  // namespace tunnelmap
