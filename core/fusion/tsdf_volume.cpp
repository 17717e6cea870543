#include "core/fusion/tsdf_volume.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "core/util/error.h"

namespace tunnelmap {

namespace {
// tsdf (4) + weight (2) + rgb (3) + colour weight (1) bytes per voxel; 2 GB is the documented memory target.
constexpr std::size_t kBytesPerVoxel = 10;
constexpr std::size_t kMaxBytes = std::size_t(1800) << 20;
}  // namespace

TsdfVolume::TsdfVolume(const VoxelGrid& grid, const TsdfOptions& options)
    : grid_(grid), options_(options) {
  if (grid.dims.minCoeff() < 2 || !(grid.voxel_m > 0))
    throw ParameterError("fusion: empty volume (no depth inside the fusion range?)");
  if (grid.count() > kMaxBytes / kBytesPerVoxel)
    throw ParameterError("fusion: volume of " + std::to_string(grid.dims.x()) + "x" +
                         std::to_string(grid.dims.y()) + "x" + std::to_string(grid.dims.z()) +
                         " voxels needs more than 1.8 GB; raise fusion.voxel_mm or lower "
                         "fusion.max_depth_m");
  tsdf_.assign(grid.count(), 1.0f);
  weight_.assign(grid.count(), 0);
  rgb_.assign(grid.count() * 3, 0);
  color_weight_.assign(grid.count(), 0);
}

std::size_t TsdfVolume::memory_bytes() const {
  return tsdf_.size() * sizeof(float) + weight_.size() * sizeof(std::uint16_t) + rgb_.size() +
         color_weight_.size();
}

void TsdfVolume::integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world) {
  if (frame.empty()) return;
  const Eigen::Isometry3d world_to_cam = camera_to_world.inverse();
  const Eigen::Matrix3f R = world_to_cam.linear().cast<float>();
  const Intrinsics& K = frame.intrinsics;
  const float fx = float(K.fx), fy = float(K.fy), cx = float(K.cx), cy = float(K.cy);
  const int W = frame.width, H = frame.height;
  const float units = float(frame.depth_units_per_m);
  const float trunc = float(options_.truncation_m), inv_trunc = 1.0f / trunc;
  const float dmin = float(options_.min_depth_m), dmax = float(options_.max_depth_m);
  const std::uint16_t wmax = static_cast<std::uint16_t>(std::clamp(options_.max_weight, 1, 65535));
  const bool colour = frame.has_rgb();
  const Eigen::Vector3f step_x = R.col(0) * float(grid_.voxel_m);  // camera-frame step per +x voxel

  auto slab = [&](int z_begin, int z_step) {
    for (int z = z_begin; z < grid_.dims.z(); z += z_step)
      for (int y = 0; y < grid_.dims.y(); ++y) {
        Eigen::Vector3f pc = (world_to_cam * grid_.position(0, y, z)).cast<float>();
        std::size_t idx = grid_.index(0, y, z);
        for (int x = 0; x < grid_.dims.x(); ++x, pc += step_x, ++idx) {
          if (pc.z() < dmin) continue;
          const float iz = 1.0f / pc.z();
          const float xn = pc.x() * iz, yn = pc.y() * iz;
          const float uf = fx * xn + cx + 0.5f, vf = fy * yn + cy + 0.5f;
          if (!(uf >= 0.0f && vf >= 0.0f && uf < float(W) && vf < float(H))) continue;
          const int u = static_cast<int>(uf), v = static_cast<int>(vf);  // nearest pixel
          const std::size_t pix = static_cast<std::size_t>(v) * W + u;
          const float d = frame.depth[pix] / units;
          if (!(d >= dmin && d <= dmax)) continue;  // also rejects NaN and 0
          // Distance along the viewing ray (not along z): the ray is sqrt(1+xn^2+yn^2) longer.
          const float sdf = (d - pc.z()) * std::sqrt(1.0f + xn * xn + yn * yn);
          if (sdf < -trunc) continue;  // hidden behind the surface: unknown, leave it
          const float t = std::min(1.0f, sdf * inv_trunc);
          const std::uint16_t w = weight_[idx];
          const float wf = float(w);
          tsdf_[idx] = (tsdf_[idx] * wf + t) / (wf + 1.0f);
          if (colour && sdf < trunc) {
            // Own weight: free-space observations must not darken the surface colour.
            const std::uint8_t* c = &frame.rgb[pix * 3];
            std::uint8_t* o = &rgb_[idx * 3];
            const float cw = float(color_weight_[idx]);
            for (int k = 0; k < 3; ++k)
              o[k] = static_cast<std::uint8_t>(std::lround((o[k] * cw + c[k]) / (cw + 1.0f)));
            if (color_weight_[idx] < std::min<int>(wmax, 255)) ++color_weight_[idx];
          }
          weight_[idx] = std::min<std::uint16_t>(static_cast<std::uint16_t>(w + 1), wmax);
        }
      }
  };
  int threads = options_.threads > 0 ? options_.threads
                                     : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, 8);
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(slab, k, threads);
  slab(0, threads);
  for (std::thread& t : pool) t.join();
  ++frames_;
}

}  // namespace tunnelmap
