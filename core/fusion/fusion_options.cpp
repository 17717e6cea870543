#include "core/fusion/fusion_options.h"

#include <cmath>
#include <string>

#include "core/util/error.h"

namespace tunnelmap {

FusionOptions fusion_options(const Parameters& p) {
  FusionOptions o;
  o.voxel_m = p.get("fusion.voxel_mm") / 1000.0;
  o.truncation_m = p.get("fusion.truncation_mm") / 1000.0;
  o.min_depth_m = p.get("cloud.min_range_m");
  o.max_depth_m = p.get("fusion.max_depth_m");
  o.max_weight = p.get_int("fusion.max_weight");
  o.min_weight = p.get_int("fusion.min_weight");
  o.bounds_margin_m = p.get("fusion.bounds_margin_m");
  o.max_extent_m = p.get("fusion.max_extent_m");
  o.pose_group_m = p.get("fusion.pose_group_mm") / 1000.0;
  return o;
}

TsdfOptions tsdf_options(const FusionOptions& o) {
  TsdfOptions t;
  t.truncation_m = o.truncation_m;
  t.min_depth_m = o.min_depth_m;
  t.max_depth_m = o.max_depth_m;
  t.max_weight = o.max_weight;
  return t;
}

void extend_depth_bounds(const DepthFrame& f, const Eigen::Isometry3d& T, const FusionOptions& o,
                         Eigen::AlignedBox3d& box, int stride) {
  stride = std::max(1, stride);
  for (int v = 0; v < f.height; v += stride)
    for (int u = 0; u < f.width; u += stride) {
      const double d = f.depth_m(u, v);
      if (!(d >= o.min_depth_m && d <= o.max_depth_m)) continue;
      box.extend(T * f.intrinsics.backproject(float(u), float(v), float(d)).cast<double>());
    }
}

VoxelGrid fusion_grid(const Eigen::AlignedBox3d& box, const FusionOptions& o) {
  if (box.isEmpty())
    throw ParameterError("fusion: no depth within [" + std::to_string(o.min_depth_m) + ", " +
                         std::to_string(o.max_depth_m) + "] m in any posed frame");
  const Eigen::Vector3d lo = box.min() - Eigen::Vector3d::Constant(o.bounds_margin_m);
  const Eigen::Vector3d hi = box.max() + Eigen::Vector3d::Constant(o.bounds_margin_m);
  const Eigen::Vector3d size = hi - lo;
  if (size.maxCoeff() > o.max_extent_m)
    throw ParameterError("fusion: the data spans " + std::to_string(size.maxCoeff()) +
                         " m, more than fusion.max_extent_m = " + std::to_string(o.max_extent_m));
  VoxelGrid g;
  g.voxel_m = o.voxel_m;
  g.origin = lo;
  for (int k = 0; k < 3; ++k) g.dims[k] = static_cast<int>(std::ceil(size[k] / o.voxel_m)) + 1;
  return g;
}

}  // namespace tunnelmap
