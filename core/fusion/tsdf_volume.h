#pragma once
// TsdfVolume: a dense, axis-aligned truncated signed distance volume with colour (Curless &
// Levoy 1996; KinectFusion's projective update). Each frame is integrated at a GIVEN camera
// pose (no tracking: the arm's kinematics provide it). Why our own and not OpenCV's
// cv::kinfu TSDF: docs/fusion.md (OpenCV 4.6 gives no access to the voxel values, so no mesh).
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/fusion/tsdf_update.h"

namespace tunnelmap {

struct VoxelGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // world position of voxel (0,0,0)'s centre
  double voxel_m = 0.01;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();    // voxels along x, y, z

  std::size_t count() const {
    return static_cast<std::size_t>(dims.x()) * dims.y() * dims.z();
  }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * dims.y() + y) * dims.x() + x;
  }
  Eigen::Vector3d position(int x, int y, int z) const {
    return origin + voxel_m * Eigen::Vector3d(x, y, z);
  }
};

class TsdfVolume {
 public:
  // Throws ParameterError when the grid is empty or would need more than ~2 GB.
  TsdfVolume(const VoxelGrid& grid, const TsdfOptions& options);

  // Fuses one depth frame (and its registered colour, if any) seen from `camera_to_world`.
  void integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world);

  const VoxelGrid& grid() const { return grid_; }
  const TsdfOptions& options() const { return options_; }
  // Normalised distance in [-1, 1] (positive in front of surfaces), 1 where never seen.
  const std::vector<float>& tsdf() const { return tsdf_; }
  const std::vector<std::uint16_t>& weight() const { return weight_; }
  const std::vector<std::uint8_t>& rgb() const { return rgb_; }  // 3 per voxel
  int frames_integrated() const { return frames_; }
  std::size_t memory_bytes() const;

 private:
  VoxelGrid grid_;
  TsdfOptions options_;
  std::vector<float> tsdf_;
  std::vector<std::uint16_t> weight_;
  std::vector<std::uint8_t> rgb_;
  std::vector<std::uint8_t> color_weight_;
  int frames_ = 0;
};

}  // namespace tunnelmap
