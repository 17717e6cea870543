#include "core/fusion/tsdf_volume.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "core/fusion/fusion_error.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {
// tsdf (4) + weight (2) + rgb (3) + colour weight (1) bytes per voxel; 2 GB is the documented memory target.
constexpr std::size_t kBytesPerVoxel = 10;
}  // namespace

TsdfVolume::TsdfVolume(const VoxelGrid& grid, const TsdfOptions& options)
    : grid_(grid), options_(options) {
  if (grid.dims.minCoeff() < 2 || !(grid.voxel_m > 0))
    throw FusionDataError("fusion: empty volume (no depth inside the fusion range?)");
  if (grid.count() > options.max_bytes / kBytesPerVoxel)
    throw FusionDataError("fusion: volume of " + std::to_string(grid.dims.x()) + "x" +
                         std::to_string(grid.dims.y()) + "x" + std::to_string(grid.dims.z()) +
                         " voxels needs more than fusion.max_volume_mb = " +
                         std::to_string(options.max_bytes >> 20) + " MiB; raise fusion.voxel_mm or lower "
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
  const FrameProjection fp(frame, options_);
  const Eigen::Vector3f step_x = R.col(0) * float(grid_.voxel_m);  // camera-frame step per +x voxel

  auto slab = [&](int z_begin, int z_step) {
    for (int z = z_begin; z < grid_.dims.z(); z += z_step)
      for (int y = 0; y < grid_.dims.y(); ++y) {
        Eigen::Vector3f pc = (world_to_cam * grid_.position(0, y, z)).cast<float>();
        std::size_t idx = grid_.index(0, y, z);
        for (int x = 0; x < grid_.dims.x(); ++x, pc += step_x, ++idx)
          update_voxel(fp, pc, tsdf_[idx], weight_[idx], &rgb_[idx * 3], color_weight_[idx]);
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
