#pragma once
// The sparse volume's lattice moved by less than a block along each of its axes so that the
// frames' truncation bands allocate as few blocks as they can. A wall's band (two truncations
// thick) fits in one layer of blocks when the wall lies near a block's middle and spans two
// when it lies near a block boundary: without the move the same girder costs up to 1.4 x the
// blocks depending on where the world's origin happens to be (docs/fusion.md). The offset is
// fitted from the depth data (where the surfaces are), so a rigid motion of the whole world
// moves the lattice with it. Fitted once, after the heading and before the first integration.
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/fusion/tsdf_update.h"

namespace tunnelmap {

// A depth frame and its pose, one of the frames the offset is fitted on.
struct PosedDepth {
  DepthFrame frame;
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
};

struct LatticeOffsetFit {
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // lattice axes, each in [0, block)
  std::size_t blocks_at_zero = 0;  // the sample's blocks with the lattice's origin at the world's
  std::size_t blocks_fitted = 0;   // and at the fitted offset
  int evaluations = 0;             // band walks of the whole sample
};

// Every kOffsetFitRowStep-th row of each sampled frame, every column. The same number of
// pixels as every 4th pixel of every 4th row, but that sample missed ~5 % of the blocks the
// whole frames allocate and chose an offset that cost 7 % more blocks than this one (measured
// on a 10 m walk, docs/fusion.md).
inline constexpr int kOffsetFitRowStep = 16;

// `count` frame indices spread evenly over `frames` frames (all of them when fewer).
std::vector<std::size_t> evenly_spread(std::size_t frames, std::size_t count);

// Every `step`-th row, with intrinsics that give each kept pixel its original ray (depth only).
DepthFrame every_nth_row(const DepthFrame& frame, int step);

// The offset (whole voxels, fewer than kBlockSide per axis) at which the sample's bands
// allocate the fewest blocks, by coordinate descent over the lattice's y, z and x (the axes are
// nearly separable: a wall normal to y costs its layers along y times its area).
LatticeOffsetFit fit_lattice_offset(const std::vector<PosedDepth>& sample, const Eigen::Matrix3d& lattice_to_world,
                                    double voxel_m, const TsdfOptions& options);

}  // namespace tunnelmap
