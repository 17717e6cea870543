#pragma once
// The blocks a depth frame's truncation band passes through: for every valid pixel, the
// segment [d - truncation, d + truncation] along its ray, sampled at most half a block apart
// (so the band cannot cross a block without a sample inside it, but at a corner). Shared by
// the sparse volume and the OpenVDB peer in bench/ so both allocate the same blocks.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/fusion/tsdf_update.h"

namespace tunnelmap {

// Block index of a world point, for a given block edge.
inline Eigen::Vector3i block_of(const Eigen::Vector3f& p, float block_m) {
  return {static_cast<int>(std::floor(p.x() / block_m)), static_cast<int>(std::floor(p.y() / block_m)),
          static_cast<int>(std::floor(p.z() / block_m))};
}

// Calls `visit(block)` for the blocks of the frame's band; a block may
// come more than once (consecutive pixels' repeats are skipped, the caller removes the rest).
template <typename Visit>
void for_each_band_block(const FrameProjection& fp, const Eigen::Isometry3d& camera_to_world,
                         float block_m, Visit&& visit) {
  constexpr float kStepOfBlock = 0.5f;
  constexpr int kMaxSamples = 32;
  const Eigen::Matrix3f R = camera_to_world.linear().cast<float>();
  const Eigen::Vector3f t = camera_to_world.translation().cast<float>();
  // Consecutive pixels mostly hit the same blocks at the same sample: skip those repeats.
  std::array<Eigen::Vector3i, kMaxSamples> last;
  for (Eigen::Vector3i& k : last) k.setConstant(std::numeric_limits<int>::min());
  for (int v = 0; v < fp.height; ++v)
    for (int u = 0; u < fp.width; ++u) {
      const float d = fp.depth[static_cast<std::size_t>(v) * fp.width + u] / fp.units_per_m;
      if (!(d >= fp.dmin && d <= fp.dmax)) continue;
      const Eigen::Vector3f ray((float(u) - fp.cx) / fp.fx, (float(v) - fp.cy) / fp.fy, 1.0f);
      const Eigen::Vector3f dir = R * ray;
      const float half_band = fp.trunc / ray.norm();  // in depth (z) units
      const Eigen::Vector3f near = t + dir * (d - half_band), far = t + dir * (d + half_band);
      const int samples = std::min(
          kMaxSamples, static_cast<int>(std::ceil((far - near).norm() / (kStepOfBlock * block_m))) + 1);
      for (int s = 0; s < samples; ++s) {
        const float a = float(s) / float(samples - 1);
        const Eigen::Vector3i key = block_of(near + a * (far - near), block_m);
        if (key == last[static_cast<std::size_t>(s)]) continue;
        last[static_cast<std::size_t>(s)] = key;
        visit(key);
      }
    }
}

}  // namespace tunnelmap
