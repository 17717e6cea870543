#include "core/fusion/sparse_tsdf_volume.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>
#include <thread>

#include "core/fusion/fusion_error.h"
#include "core/fusion/truncation_band.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

int thread_count(int requested) {
  const int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(n, 1, 8);
}

}  // namespace

SparseTsdfVolume::SparseTsdfVolume(double voxel_m, const TsdfOptions& options,
                                   const SparseVolumeLimits& limits, const Eigen::Matrix3d& lattice_to_world,
                                   const Eigen::Vector3d& lattice_origin)
    : voxel_m_(voxel_m), options_(options), limits_(limits), lattice_to_world_(lattice_to_world),
      lattice_origin_(lattice_origin) {
  if (!(voxel_m > 0)) throw ParameterError("fusion: the voxel size must be positive");
  const int threads = thread_count(options.threads);
  if (threads > 1) arena_ = std::make_unique<tbb::task_arena>(threads);
}

std::size_t SparseTsdfVolume::memory_bytes() const {
  // A node of the index holds the key, the value and the next pointer (and its cached hash).
  constexpr std::size_t kNodeBytes = sizeof(void*) + sizeof(Eigen::Vector3i) + sizeof(std::int32_t) +
                                     sizeof(std::size_t);
  return blocks_.size() * (sizeof(VoxelBlock) + sizeof(void*) + sizeof(Eigen::Vector3i)) + index_.size() * kNodeBytes +
         index_.bucket_count() * sizeof(void*);
}

const VoxelBlock* SparseTsdfVolume::find(const Eigen::Vector3i& coords) const {
  const auto it = index_.find(coords);
  return it == index_.end() ? nullptr : blocks_[static_cast<std::size_t>(it->second)].get();
}

std::vector<Eigen::Vector3i> SparseTsdfVolume::blocks_touched_since(int first_frame) const {
  std::vector<Eigen::Vector3i> out;
  for (const auto& b : blocks_)
    if (b->touched_frame >= first_frame) out.push_back(b->coords);
  return out;
}

std::size_t SparseTsdfVolume::release_blocks_below(int axis, int coord) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    if (block_coords_[i][axis] < coord) {
      index_.erase(block_coords_[i]);
      blocks_[i].reset();
      continue;
    }
    if (kept != i) {
      blocks_[kept] = std::move(blocks_[i]);
      block_coords_[kept] = block_coords_[i];
      index_[block_coords_[kept]] = static_cast<std::int32_t>(kept);
    }
    ++kept;
  }
  const std::size_t released = blocks_.size() - kept;
  blocks_.resize(kept);
  block_coords_.resize(kept);
  touched_.clear();
  if (kept == 0) {
    blocks_.shrink_to_fit();
    block_coords_.shrink_to_fit();
    index_ = {};
  }
  return released;
}

VoxelBlock& SparseTsdfVolume::block_at(const Eigen::Vector3i& coords) {
  const auto [it, inserted] = index_.try_emplace(coords, static_cast<std::int32_t>(blocks_.size()));
  if (!inserted) return *blocks_[static_cast<std::size_t>(it->second)];
  Eigen::AlignedBox3i grown = block_box_;
  grown.extend(coords);
  const double span = double((grown.max() - grown.min()).maxCoeff() + 1) * block_m();
  const bool too_long = span > limits_.max_extent_m;
  const bool too_big = (blocks_.size() + 1) * sizeof(VoxelBlock) > limits_.max_bytes;
  if (too_long || too_big) {
    index_.erase(it);
    if (too_long)
      throw FusionDataError("fusion: the data spans " + std::to_string(span) +
                           " m, more than fusion.max_extent_m = " + std::to_string(limits_.max_extent_m));
    throw FusionDataError("fusion: the observed surface needs more than fusion.max_volume_mb = " +
                         std::to_string(limits_.max_bytes >> 20) + " MiB of voxel blocks; raise "
                         "fusion.voxel_mm or lower fusion.max_depth_m");
  }
  block_box_ = grown;
  auto b = std::make_unique<VoxelBlock>();
  b->coords = coords;
  b->tsdf.fill(1.0f);
  b->weight.fill(0);
  b->rgb.fill(0);
  b->color_weight.fill(0);
  blocks_.push_back(std::move(b));
  block_coords_.push_back(coords);
  return *blocks_.back();
}

// Every block of the frame's truncation band, once each, into touched_.
void SparseTsdfVolume::allocate_band(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_lattice) {
  touched_.clear();
  for_each_band_block(FrameProjection(frame, options_), camera_to_lattice, float(block_m()),
                      [&](const Eigen::Vector3i& key) {
                        VoxelBlock& b = block_at(key);
                        if (b.touched_frame == frames_) return;
                        b.touched_frame = frames_;
                        touched_.push_back(&b);
                      });
}

// Allocated blocks the frame sees without its band passing them: their voxels get the frame's
// free-space observations, as every voxel of the dense volume does (otherwise a surface that
// one frame put there and later frames see through would never be carved away).
void SparseTsdfVolume::add_visible_blocks(const FrameProjection& fp, const Eigen::Isometry3d& lattice_to_cam) {
  const double half = 0.5 * block_m();
  const double radius = half * std::sqrt(3.0);
  for (std::size_t i = 0; i < block_coords_.size(); ++i) {
    const Eigen::Vector3d c = lattice_to_cam * ((block_coords_[i].cast<double>().array() + 0.5).matrix() * block_m() -
                                                Eigen::Vector3d::Constant(0.5 * voxel_m_));
    if (c.z() + radius < fp.dmin || c.z() - radius > fp.dmax) continue;
    const double z = std::max(c.z() - radius, double(fp.dmin));
    const double u = fp.fx * c.x() / z + fp.cx, v = fp.fy * c.y() / z + fp.cy;
    const double mu = fp.fx * radius / z, mv = fp.fy * radius / z;
    if (u < -mu || v < -mv || u > fp.width + mu || v > fp.height + mv) continue;
    VoxelBlock& b = *blocks_[i];
    if (b.touched_frame == frames_) continue;
    b.touched_frame = frames_;
    touched_.push_back(&b);
  }
}

void SparseTsdfVolume::integrate_block(VoxelBlock& b, const FrameProjection& fp,
                                       const Eigen::Isometry3d& lattice_to_cam) const {
  const Eigen::Matrix3f R = lattice_to_cam.linear().cast<float>();
  const float step = float(voxel_m_);
  const Eigen::Vector3f sx = R.col(0) * step, sy = R.col(1) * step, sz = R.col(2) * step;
  const Eigen::Vector3f first = (lattice_to_cam * (b.coords.cast<double>() * kBlockSide * voxel_m_)).cast<float>();
  int idx = 0;
  for (int z = 0; z < kBlockSide; ++z)
    for (int y = 0; y < kBlockSide; ++y) {
      Eigen::Vector3f pc = first + float(z) * sz + float(y) * sy;
      for (int x = 0; x < kBlockSide; ++x, pc += sx, ++idx)
        update_voxel(fp, pc, b.tsdf[idx], b.weight[idx], &b.rgb[std::size_t(idx) * 3], b.color_weight[idx]);
    }
}

void SparseTsdfVolume::integrate(const DepthFrame& frame, const Eigen::Isometry3d& camera_to_world) {
  if (frame.empty()) return;
  Eigen::Isometry3d camera_to_lattice = Eigen::Isometry3d::Identity();
  camera_to_lattice.linear() = lattice_to_world_.transpose() * camera_to_world.linear();
  camera_to_lattice.translation() = lattice_to_world_.transpose() * (camera_to_world.translation() - lattice_origin_);
  allocate_band(frame, camera_to_lattice);
  const FrameProjection fp(frame, options_);
  const Eigen::Isometry3d lattice_to_cam = camera_to_lattice.inverse();
  add_visible_blocks(fp, lattice_to_cam);
  auto run = [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) integrate_block(*touched_[i], fp, lattice_to_cam);
  };
  const tbb::blocked_range<std::size_t> all(0, touched_.size(), 16);
  if (arena_)
    arena_->execute([&] { tbb::parallel_for(all, run); });
  else
    run(all);
  ++frames_;
}

}  // namespace tunnelmap
