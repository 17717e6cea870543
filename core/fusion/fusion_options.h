#pragma once
// Fusion settings from the parameter table (fusion.*), and the volume that encloses the data.
#include <Eigen/Geometry>

#include "core/frame/depth_frame.h"
#include "core/fusion/tsdf_volume.h"
#include "core/params/parameters.h"

namespace tunnelmap {

struct FusionOptions {
  double voxel_m = 0.008;
  double truncation_m = 0.03;
  double min_depth_m = 0.3;  // cloud.min_range_m
  double max_depth_m = 2.5;
  int max_weight = 64;
  int min_weight = 2;
  double bounds_margin_m = 0.05;
  double max_extent_m = 12.0;
  double pose_group_m = 0.05;
};

FusionOptions fusion_options(const Parameters& p);
TsdfOptions tsdf_options(const FusionOptions& o);

// Grows `box` by the world positions of the frame's depth pixels inside the fusion depth range
// (every `stride`-th pixel in both directions).
void extend_depth_bounds(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world,
                         const FusionOptions& o, Eigen::AlignedBox3d& box, int stride = 4);

// The voxel grid covering `box` plus the margin. ParameterError when the box is empty or a
// side exceeds fusion.max_extent_m.
VoxelGrid fusion_grid(const Eigen::AlignedBox3d& box, const FusionOptions& o);

}  // namespace tunnelmap
