#include "core/fusion/lattice_offset.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/fusion/sparse_tsdf_volume.h"

namespace tunnelmap {

namespace {

constexpr int kTrials = 64;  // offsets tried per block

// How far the walls at `positions` (lattice coordinates before the move) lie from the middle of
// their blocks, squared and summed (two walls out of phase share the distance), with the lattice moved by `offset`: voxel i's centre is at i * voxel, so
// a block spans [b B - voxel / 2, (b + 1) B - voxel / 2).
double off_middle(const std::vector<double>& positions, double offset, double block, double voxel) {
  double sum = 0.0;
  for (double c : positions) {
    const double u = (c - offset + 0.5 * voxel) / block;
    const double off = u - std::floor(u) - 0.5;
    sum += off * off;
  }
  return sum;
}

double best_offset(const std::vector<double>& positions, double block, double voxel) {
  double best = 0.0, best_cost = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kTrials; ++i) {
    const double offset = block * i / kTrials;
    const double cost = off_middle(positions, offset, block, voxel);
    if (cost < best_cost - 1e-12) best = offset, best_cost = cost;
  }
  return best;
}

}  // namespace

Eigen::Vector3d wall_centred_origin(const TunnelMap& merged, const Eigen::Matrix3d& lattice_to_world, double voxel_m) {
  if (!merged.detected) return Eigen::Vector3d::Zero();
  const double across = std::cos(M_PI / 180.0);
  std::vector<double> positions[3];
  for (const Wall& w : merged.walls) {
    if (!w.found || w.normal.isZero(0.0)) continue;
    const Eigen::Vector3d n = lattice_to_world.transpose() * w.normal.normalized();
    for (int k = 0; k < 3; ++k)
      if (std::abs(n[k]) >= across) positions[k].push_back(-w.offset_m / w.normal.norm() / n[k]);
  }
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // lattice frame
  for (int k = 0; k < 3; ++k)
    if (!positions[k].empty()) offset[k] = best_offset(positions[k], voxel_m * kBlockSide, voxel_m);
  return lattice_to_world * offset;
}

}  // namespace tunnelmap
