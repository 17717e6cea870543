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

// floor(x) as an int, without a call to floorf (the baseline x86-64 target has no rounding
// instruction): the same value for every x within int range.
inline int floor_to_int(float x) {
  const int i = static_cast<int>(x);  // towards zero
  return x < static_cast<float>(i) ? i - 1 : i;
}

// Block index of a world point, for a given block edge.
inline Eigen::Vector3i block_of(const Eigen::Vector3f& p, float block_m) {
  return {floor_to_int(p.x() / block_m), floor_to_int(p.y() / block_m), floor_to_int(p.z() / block_m)};
}

// Calls `visit(block)` for the blocks of the frame's band; a block may come more than once
// (the caller removes the repeats), but most repeats are skipped here, which is most of the
// walk's cost: a sample's block is skipped when the previous pixel's same sample or a small
// table of recently seen blocks (direct-mapped by the block hash) had it.
template <typename Visit>
void for_each_band_block(const FrameProjection& fp, const Eigen::Isometry3d& camera_to_world,
                         float block_m, Visit&& visit) {
  constexpr float kStepOfBlock = 0.5f;
  constexpr int kMaxSamples = 32;
  constexpr std::size_t kSeenSlots = 4096;  // a power of two; a few rows' worth of blocks
  const Eigen::Matrix3f R = camera_to_world.linear().cast<float>();
  const Eigen::Vector3f t = camera_to_world.translation().cast<float>();
  // The band is 2 truncations long along every ray (far - near = 2 trunc dir / |ray|, and the
  // rotation keeps |dir| = |ray|): the same samples for every pixel.
  const int samples = std::clamp(static_cast<int>(std::ceil(2.0f * fp.trunc / (kStepOfBlock * block_m))) + 1, 2, kMaxSamples);
  std::array<float, kMaxSamples> along{};
  for (int s = 0; s < samples; ++s) along[static_cast<std::size_t>(s)] = float(s) / float(samples - 1);
  constexpr int kNone = std::numeric_limits<int>::min();
  std::array<Eigen::Vector3i, kMaxSamples> last;
  for (Eigen::Vector3i& k : last) k.setConstant(kNone);
  std::array<Eigen::Vector3i, kSeenSlots> seen;
  for (Eigen::Vector3i& k : seen) k.setConstant(kNone);
  // The rays' x per column, computed once (columns past the table, if any, on the fly).
  constexpr int kTableColumns = 4096;
  std::array<float, kTableColumns> ray_x;
  for (int u = 0; u < std::min(fp.width, kTableColumns); ++u)
    ray_x[static_cast<std::size_t>(u)] = (float(u) - fp.cx) / fp.fx;
  for (int v = 0; v < fp.height; ++v) {
    const float ray_y = (float(v) - fp.cy) / fp.fy;
    const float* depth_row = fp.depth + static_cast<std::size_t>(v) * fp.width;
    for (int u = 0; u < fp.width; ++u) {
      const float d = depth_row[u] / fp.units_per_m;
      if (!(d >= fp.dmin && d <= fp.dmax)) continue;
      const float rx = u < kTableColumns ? ray_x[static_cast<std::size_t>(u)] : (float(u) - fp.cx) / fp.fx;
      const Eigen::Vector3f ray(rx, ray_y, 1.0f);
      const Eigen::Vector3f dir = R * ray;
      const float half_band = fp.trunc / ray.norm();  // in depth (z) units
      const Eigen::Vector3f near = t + dir * (d - half_band), far = t + dir * (d + half_band);
      for (int s = 0; s < samples; ++s) {
        const Eigen::Vector3i key = block_of(near + along[static_cast<std::size_t>(s)] * (far - near), block_m);
        Eigen::Vector3i& previous = last[static_cast<std::size_t>(s)];
        if (key == previous) continue;
        previous = key;
        const std::size_t slot =
            (static_cast<std::size_t>(key.x()) * 73856093u ^ static_cast<std::size_t>(key.y()) * 19349663u ^
             static_cast<std::size_t>(key.z()) * 83492791u) & (kSeenSlots - 1);
        if (seen[slot] == key) continue;
        seen[slot] = key;
        visit(key);
      }
    }
  }
}

}  // namespace tunnelmap
