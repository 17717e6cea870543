#pragma once
// Fusion's parameters (fusion.*), declared once, its options, and the volume that encloses the data.
#include <Eigen/Geometry>

#include "core/frame/depth_frame.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/tsdf_volume.h"
#include "core/normals/cloud_options.h"
#include "core/params/parameter_key.h"
#include "core/params/parameters.h"
#include "core/fusion/fusion_error.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace fusion_keys {
// Not from the paper: sensible values for a VGA structured-light camera in a ~1 m tunnel
// (docs/fusion.md).
inline constexpr ParameterKey<double> voxel_mm{
    "fusion.voxel_mm", "mm", 8.0, 2.0, 50.0, 0.5, Stage::Fusion, "Voxel size",
    "Edge of one TSDF voxel; memory grows with its inverse cube"};
inline constexpr ParameterKey<double> truncation_mm{
    "fusion.truncation_mm", "mm", 30.0, 5.0, 200.0, 1.0, Stage::Fusion, "Truncation",
    "TSDF truncation distance; at least ~3 voxels and above the depth noise"};
inline constexpr ParameterKey<double> max_depth_m{
    "fusion.max_depth_m", "m", 2.5, 0.5, 10.0, 0.1, Stage::Fusion, "Fusion max depth",
    "Depth beyond this is not fused (structured-light noise grows with depth squared)"};
inline constexpr ParameterKey<int> max_weight{
    "fusion.max_weight", "", 64, 1, 10000, 1, Stage::Fusion, "Max weight",
    "Cap of a voxel's running-average weight (frames); lower adapts faster to pose changes"};
inline constexpr ParameterKey<int> min_weight{
    "fusion.min_weight", "", 2, 1, 1000, 1, Stage::Fusion, "Min weight",
    "Mesh only cells whose 8 voxels were seen at least this many times"};
inline constexpr ParameterKey<double> bounds_margin_m{
    "fusion.bounds_margin_m", "m", 0.05, 0.0, 2.0, 0.01, Stage::Fusion, "Bounds margin",
    "The dense volume (fuse --dense) is the box of all fused points grown by this margin"};
inline constexpr ParameterKey<double> max_extent_m{
    "fusion.max_extent_m", "m", 2000.0, 0.5, 10000.0, 0.5, Stage::Fusion, "Max extent",
    "Safety limit on the fused data's span along a world axis, far above any girder (memory "
    "follows the surface, not this box)"};
inline constexpr ParameterKey<int> max_volume_mb{
    "fusion.max_volume_mb", "MiB", 1800, 1, 65536, 1, Stage::Fusion, "Volume memory budget",
    "Most memory the fused volume may take; a surface that needs more is refused before it is "
    "allocated (raise fusion.voxel_mm or lower fusion.max_depth_m)"};
inline constexpr ParameterKey<double> pose_group_mm{
    "fusion.pose_group_mm", "mm", 50.0, 1.0, 1000.0, 1.0, Stage::Fusion, "Pose grouping",
    "Consecutive frames whose camera moved less than this (and 5 deg) are one arm pose"};
inline constexpr ParameterKey<int> offset_fit_frames{
    "fusion.offset_fit_frames", "", 16, 0, 1000, 1, Stage::Fusion, "Lattice offset fit frames",
    "Frames (spread evenly over the walk) whose truncation bands choose the sparse lattice's "
    "offset that allocates the fewest blocks; 0 keeps the lattice's origin at the world's"};
}  // namespace fusion_keys

struct FusionOptions {
  double voxel_m = mm_to_m(fusion_keys::voxel_mm.default_value);
  double truncation_m = mm_to_m(fusion_keys::truncation_mm.default_value);
  double min_depth_m = cloud_keys::min_range_m.default_value;  // the cloud's near limit
  double max_depth_m = fusion_keys::max_depth_m.default_value;
  int max_weight = fusion_keys::max_weight.default_value;
  int min_weight = fusion_keys::min_weight.default_value;
  double bounds_margin_m = fusion_keys::bounds_margin_m.default_value;
  double max_extent_m = fusion_keys::max_extent_m.default_value;
  std::size_t max_volume_bytes = std::size_t(fusion_keys::max_volume_mb.default_value) << 20;
  double pose_group_m = mm_to_m(fusion_keys::pose_group_mm.default_value);
  int offset_fit_frames = fusion_keys::offset_fit_frames.default_value;
};
bool operator==(const FusionOptions& a, const FusionOptions& b);
inline bool operator!=(const FusionOptions& a, const FusionOptions& b) { return !(a == b); }

FusionOptions fusion_options(const Parameters& p);
ParameterGroup fusion_parameter_group();  // table rows and rules, in table order
TsdfOptions tsdf_options(const FusionOptions& o);
SparseVolumeLimits sparse_volume_limits(const FusionOptions& o);

// Grows `box` by the world positions of the frame's depth pixels inside the fusion depth range
// (every `stride`-th pixel in both directions).
void extend_depth_bounds(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world,
                         const FusionOptions& o, Eigen::AlignedBox3d& box, int stride = 4);

// What fusing frames without any depth in the fusion range throws.
FusionDataError no_depth_error(const FusionOptions& o);

// The dense voxel grid covering `box` plus the margin. ParameterError when the box is empty or a
// side exceeds fusion.max_extent_m.
VoxelGrid fusion_grid(const Eigen::AlignedBox3d& box, const FusionOptions& o);

}  // namespace tunnelmap
