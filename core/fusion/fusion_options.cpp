#include "core/fusion/fusion_options.h"

#include <cmath>
#include <string>

#include "core/util/error.h"

namespace tunnelmap {

bool operator==(const FusionOptions& a, const FusionOptions& b) {
  return a.voxel_m == b.voxel_m && a.truncation_m == b.truncation_m && a.min_depth_m == b.min_depth_m &&
         a.max_depth_m == b.max_depth_m && a.max_weight == b.max_weight && a.min_weight == b.min_weight &&
         a.bounds_margin_m == b.bounds_margin_m && a.max_extent_m == b.max_extent_m && a.max_volume_bytes == b.max_volume_bytes &&
         a.pose_group_m == b.pose_group_m && a.offset_fit_frames == b.offset_fit_frames;
}

FusionOptions fusion_options(const Parameters& p) {
  using namespace fusion_keys;
  FusionOptions o;
  o.voxel_m = mm_to_m(p.get(voxel_mm));
  o.truncation_m = mm_to_m(p.get(truncation_mm));
  o.min_depth_m = p.get(cloud_keys::min_range_m);
  o.max_depth_m = p.get(max_depth_m);
  o.max_weight = p.get(max_weight);
  o.min_weight = p.get(min_weight);
  o.bounds_margin_m = p.get(bounds_margin_m);
  o.max_extent_m = p.get(max_extent_m);
  o.max_volume_bytes = std::size_t(p.get(max_volume_mb)) << 20;
  o.pose_group_m = mm_to_m(p.get(pose_group_mm));
  o.offset_fit_frames = p.get(offset_fit_frames);
  return o;
}

ParameterGroup fusion_parameter_group() {
  using namespace fusion_keys;
  return {{voxel_mm.spec(), truncation_mm.spec(), max_depth_m.spec(), max_weight.spec(), min_weight.spec(),
           bounds_margin_m.spec(), max_extent_m.spec(), max_volume_mb.spec(), pose_group_mm.spec(),
           offset_fit_frames.spec()},
          {}};
}

TsdfOptions tsdf_options(const FusionOptions& o) {
  TsdfOptions t;
  t.truncation_m = o.truncation_m;
  t.min_depth_m = o.min_depth_m;
  t.max_depth_m = o.max_depth_m;
  t.max_weight = o.max_weight;
  t.max_bytes = o.max_volume_bytes;
  return t;
}

SparseVolumeLimits sparse_volume_limits(const FusionOptions& o) {
  SparseVolumeLimits l;
  l.max_extent_m = o.max_extent_m;
  l.max_bytes = o.max_volume_bytes;
  return l;
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

FusionDataError no_depth_error(const FusionOptions& o) {
  return FusionDataError("fusion: no depth within [" + std::to_string(o.min_depth_m) + ", " +
                        std::to_string(o.max_depth_m) + "] m in any posed frame");
}

VoxelGrid fusion_grid(const Eigen::AlignedBox3d& box, const FusionOptions& o) {
  if (box.isEmpty()) throw no_depth_error(o);
  const Eigen::Vector3d lo = box.min() - Eigen::Vector3d::Constant(o.bounds_margin_m);
  const Eigen::Vector3d hi = box.max() + Eigen::Vector3d::Constant(o.bounds_margin_m);
  const Eigen::Vector3d size = hi - lo;
  if (size.maxCoeff() > o.max_extent_m)
    throw FusionDataError("fusion: the data spans " + std::to_string(size.maxCoeff()) +
                         " m, more than " + std::string(fusion_keys::max_extent_m.key) + " = " + std::to_string(o.max_extent_m));
  // On the sparse volume's lattice (voxel centres at multiples of the voxel size), so that the
  // two volumes sample the same points and their meshes can be compared vertex for vertex.
  VoxelGrid g;
  g.voxel_m = o.voxel_m;
  g.origin = (lo / o.voxel_m).array().floor().matrix() * o.voxel_m;
  for (int k = 0; k < 3; ++k) g.dims[k] = static_cast<int>(std::ceil((hi[k] - g.origin[k]) / o.voxel_m)) + 1;
  return g;
}

}  // namespace tunnelmap
