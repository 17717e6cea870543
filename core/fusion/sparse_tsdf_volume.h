#pragma once
// SparseTsdfVolume: the TSDF in blocks of 8 x 8 x 8 voxels, allocated only where some frame's
// truncation band passed (voxel hashing, Niessner et al. 2013), so that memory and time follow
// the observed surface instead of the bounding box. Voxel (i, j, k) of the lattice has its
// centre at voxel_m * (i, j, k) in the lattice frame: the world frame turned by
// `lattice_to_world` and moved to `lattice_origin` (fusion turns it with the girder's heading,
// so that walls lie along lattice planes and a girder running diagonally in the world costs
// the same, and moves it by less than a block so that the walls' bands cross as few block
// layers as they can; docs/fusion.md). Each frame allocates the blocks along every valid
// pixel's truncation band, then updates only those blocks' voxels, with the same per-voxel rule
// as the dense TsdfVolume (core/fusion/tsdf_update.h). Why blocks in a hash map and not
// OpenVDB: docs/fusion.md.
#include <tbb/task_arena.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/fusion/tsdf_update.h"

namespace tunnelmap {

inline constexpr int kBlockSide = 8;
inline constexpr int kBlockVoxels = kBlockSide * kBlockSide * kBlockSide;

struct VoxelBlock {
  Eigen::Vector3i coords = Eigen::Vector3i::Zero();  // block index: voxel index / kBlockSide
  int touched_frame = -1;  // the last frame that integrated this block
  std::array<float, kBlockVoxels> tsdf;               // normalised, 1 where never seen
  std::array<std::uint16_t, kBlockVoxels> weight;
  std::array<std::uint8_t, kBlockVoxels * 3> rgb;
  std::array<std::uint8_t, kBlockVoxels> color_weight;

  static int local_index(int x, int y, int z) { return (z * kBlockSide + y) * kBlockSide + x; }
};

struct BlockCoordsHash {
  std::size_t operator()(const Eigen::Vector3i& b) const {
    return static_cast<std::size_t>(b.x()) * 73856093u ^ static_cast<std::size_t>(b.y()) * 19349663u ^
           static_cast<std::size_t>(b.z()) * 83492791u;
  }
};

struct SparseVolumeLimits {
  double max_extent_m = 2000.0;  // largest span of the allocated blocks along any world axis
  std::size_t max_bytes = std::size_t(1800) << 20;
};

class SparseTsdfVolume {
 public:
  // Throws ParameterError when voxel_m is not positive.
  SparseTsdfVolume(double voxel_m, const TsdfOptions& options,
                   const SparseVolumeLimits& limits = SparseVolumeLimits(),
                   const Eigen::Matrix3d& lattice_to_world = Eigen::Matrix3d::Identity(),
                   const Eigen::Vector3d& lattice_origin = Eigen::Vector3d::Zero());

  // Fuses one depth frame (and its registered colour, if any) seen from `camera_to_world`.
  // Throws ParameterError when the new blocks break a limit (the volume is then unchanged
  // apart from the blocks already allocated by earlier frames).
  void integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world);

  double voxel_m() const { return voxel_m_; }
  double block_m() const { return voxel_m_ * kBlockSide; }
  const TsdfOptions& options() const { return options_; }
  const Eigen::Matrix3d& lattice_to_world() const { return lattice_to_world_; }
  // Where the lattice's origin lies in the world.
  const Eigen::Vector3d& lattice_origin() const { return lattice_origin_; }
  int frames_integrated() const { return frames_; }

  std::size_t block_count() const { return blocks_.size(); }
  std::size_t voxel_count() const { return blocks_.size() * kBlockVoxels; }
  // The blocks' voxels plus the hash index (its nodes and buckets).
  std::size_t memory_bytes() const;
  // In allocation order; never moved once allocated.
  const std::vector<std::unique_ptr<VoxelBlock>>& blocks() const { return blocks_; }
  const VoxelBlock* find(const Eigen::Vector3i& coords) const;
  // Blocks that frames number `first_frame` (0-based) and later integrated.
  std::vector<Eigen::Vector3i> blocks_touched_since(int first_frame) const;
  // Frees the blocks whose coordinate along `axis` (0, 1, 2) is below `coord` (a mesher that
  // sweeps along the girder frees what it has meshed); returns how many. The others keep their
  // voxels and stay in allocation order.
  std::size_t release_blocks_below(int axis, int coord);

 private:
  VoxelBlock& block_at(const Eigen::Vector3i& coords);  // allocates when new
  void allocate_band(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_lattice);
  void add_visible_blocks(const FrameProjection& fp, const Eigen::Isometry3d& lattice_to_cam);
  void integrate_block(VoxelBlock& b, const FrameProjection& fp, const Eigen::Isometry3d& lattice_to_cam) const;

  double voxel_m_;
  TsdfOptions options_;
  SparseVolumeLimits limits_;
  Eigen::Matrix3d lattice_to_world_;
  Eigen::Vector3d lattice_origin_;
  std::vector<std::unique_ptr<VoxelBlock>> blocks_;
  // Each block's coordinates again, packed: the per-frame visibility test reads these in one
  // sequential pass instead of visiting every block's 5 KiB (a long girder has 10^5 blocks).
  std::vector<Eigen::Vector3i> block_coords_;
  std::unordered_map<Eigen::Vector3i, std::int32_t, BlockCoordsHash> index_;
  Eigen::AlignedBox3i block_box_;  // of the allocated blocks
  std::vector<VoxelBlock*> touched_;  // this frame's blocks (kept: no allocation per frame)
  std::unique_ptr<tbb::task_arena> arena_;
  int frames_ = 0;
};

}  // namespace tunnelmap
