#include "core/fusion/lattice_offset.h"

#include <algorithm>
#include <unordered_set>

#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/truncation_band.h"

namespace tunnelmap {

namespace {

// The sample's poses in the lattice frame turned but not yet moved.
std::vector<Eigen::Isometry3d> cameras_in_lattice(const std::vector<PosedDepth>& sample,
                                                  const Eigen::Matrix3d& lattice_to_world) {
  std::vector<Eigen::Isometry3d> out;
  for (const PosedDepth& p : sample) {
    Eigen::Isometry3d c = Eigen::Isometry3d::Identity();
    c.linear() = lattice_to_world.transpose() * p.camera_to_world.linear();
    c.translation() = lattice_to_world.transpose() * p.camera_to_world.translation();
    out.push_back(c);
  }
  return out;
}

// The distinct blocks the sample's bands pass with the lattice's origin at `offset` (the
// volume's own band walk, so the count is what the volume would allocate for these frames).
std::size_t band_blocks(const std::vector<PosedDepth>& sample, const std::vector<Eigen::Isometry3d>& cameras,
                        const Eigen::Vector3d& offset, float block_m, const TsdfOptions& options) {
  std::unordered_set<Eigen::Vector3i, BlockCoordsHash> blocks;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    Eigen::Isometry3d moved = cameras[i];
    moved.translation() -= offset;
    for_each_band_block(FrameProjection(sample[i].frame, options), moved, block_m,
                        [&](const Eigen::Vector3i& key) { blocks.insert(key); });
  }
  return blocks.size();
}

// Tries every whole-voxel offset along `axis` with the other two kept; keeps the one with the
// fewest blocks (ties keep the offset already chosen). True when it moved.
template <typename BlocksAt>
bool best_along(int axis, double voxel_m, BlocksAt& blocks_at, LatticeOffsetFit& fit) {
  const double current = fit.offset_m[axis];
  for (int step = 0; step < kBlockSide; ++step) {
    Eigen::Vector3d candidate = fit.offset_m;
    candidate[axis] = step * voxel_m;
    if (candidate[axis] == current) continue;  // its count is known
    const std::size_t blocks = blocks_at(candidate);
    if (blocks >= fit.blocks_fitted) continue;
    fit.blocks_fitted = blocks;
    fit.offset_m = candidate;
  }
  return fit.offset_m[axis] != current;
}

}  // namespace

std::vector<std::size_t> evenly_spread(std::size_t frames, std::size_t count) {
  std::vector<std::size_t> out;
  if (frames == 0 || count == 0) return out;
  const std::size_t n = std::min(frames, count);
  for (std::size_t k = 0; k < n; ++k) out.push_back((2 * k + 1) * frames / (2 * n));  // the middles of n equal parts
  return out;
}

DepthFrame every_nth_row(const DepthFrame& f, int step) {
  DepthFrame out;
  out.depth_units_per_m = f.depth_units_per_m;
  out.intrinsics = f.intrinsics;
  out.width = f.width;
  out.height = out.intrinsics.height = (f.height + step - 1) / step;
  // Kept row v is row step v: ((step v) - cy) / fy = (v - cy / step) / (fy / step).
  out.intrinsics.fy /= step;
  out.intrinsics.cy /= step;
  out.depth.reserve(static_cast<std::size_t>(out.width) * out.height);
  for (int v = 0; v < f.height; v += step) {
    const auto row = f.depth.begin() + static_cast<std::ptrdiff_t>(v) * f.width;
    out.depth.insert(out.depth.end(), row, row + f.width);
  }
  return out;
}

LatticeOffsetFit fit_lattice_offset(const std::vector<PosedDepth>& sample, const Eigen::Matrix3d& lattice_to_world,
                                    double voxel_m, const TsdfOptions& options) {
  LatticeOffsetFit fit;
  if (sample.empty()) return fit;
  const std::vector<Eigen::Isometry3d> cameras = cameras_in_lattice(sample, lattice_to_world);
  const float block_m = float(voxel_m * kBlockSide);
  auto blocks_at = [&](const Eigen::Vector3d& offset) {
    ++fit.evaluations;
    return band_blocks(sample, cameras, offset, block_m, options);
  };
  fit.blocks_at_zero = fit.blocks_fitted = blocks_at(fit.offset_m);
  constexpr int kRounds = 2;  // a second round only when the first moved some axis
  constexpr int kAxes[] = {1, 2, 0};  // across, up, along the girder: the walls first
  bool moved = true;
  for (int round = 0; round < kRounds && moved; ++round) {
    moved = false;
    for (const int axis : kAxes) moved = best_along(axis, voxel_m, blocks_at, fit) || moved;
  }
  return fit;
}

}  // namespace tunnelmap
