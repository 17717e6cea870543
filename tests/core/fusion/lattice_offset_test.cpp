// The lattice's origin puts the merged map's walls near the middle of their blocks.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fusion/lattice_offset.h"
#include "core/fusion/sparse_tsdf_volume.h"

using namespace tunnelmap;

namespace {

constexpr double kVoxel = 0.008, kBlock = kVoxel * kBlockSide;

// A box section around the line y = y0, z = z0 along `dir` (horizontal): walls facing inwards.
TunnelMap box_map(double y0, double z0, double width, double height, const Eigen::Vector3d& dir) {
  TunnelMap m;
  m.detected = true;
  const Eigen::Vector3d side = Eigen::Vector3d::UnitZ().cross(dir).normalized();  // to the left
  const Eigen::Vector3d centre = y0 * side + z0 * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d normals[4] = {-side, side, -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};
  const Eigen::Vector3d points[4] = {centre + 0.5 * width * side, centre - 0.5 * width * side,
                                     centre + 0.5 * height * Eigen::Vector3d::UnitZ(),
                                     centre - 0.5 * height * Eigen::Vector3d::UnitZ()};
  for (int i = 0; i < 4; ++i) {
    m.walls[i].found = true;
    m.walls[i].normal = normals[i];
    m.walls[i].offset_m = -normals[i].dot(points[i]);
  }
  return m;
}

// Where `position` (lattice coordinate) lies in its block, 0..1, with the lattice moved by `origin`.
double in_block(double position, double origin) {
  const double u = (position - origin + 0.5 * kVoxel) / kBlock;
  return u - std::floor(u);
}

}  // namespace

TEST(LatticeOffset, PutsTheWallsNearTheMiddleOfTheirBlocks) {
  for (double y0 : {0.0, 0.011, 0.032, 0.05}) {
    const TunnelMap m = box_map(y0, 0.6, 0.84, 1.2, Eigen::Vector3d::UnitX());
    const Eigen::Vector3d o = wall_centred_origin(m, Eigen::Matrix3d::Identity(), kVoxel);
    EXPECT_EQ(o.x(), 0.0);  // no wall across x
    for (double y : {y0 + 0.42, y0 - 0.42}) EXPECT_NEAR(in_block(y, o.y()), 0.5, 0.07) << y0;  // 0.84 m: 8 mm apart in phase
    for (double z : {0.0, 1.2}) EXPECT_NEAR(in_block(z, o.z()), 0.5, 0.13) << y0;  // 1.2 m: a quarter block apart
    EXPECT_GE(o.minCoeff(), 0.0);
    EXPECT_LT(o.maxCoeff(), kBlock);
  }
}

TEST(LatticeOffset, FollowsATurnedLattice) {
  const double yaw = 30.0 * M_PI / 180.0;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const TunnelMap m = box_map(0.02, 0.6, 0.84, 1.2, R.col(0));
  const Eigen::Vector3d o = R.transpose() * wall_centred_origin(m, R, kVoxel);  // lattice frame
  for (double y : {0.02 + 0.42, 0.02 - 0.42}) EXPECT_NEAR(in_block(y, o.y()), 0.5, 0.07);
}

TEST(LatticeOffset, NoMoveWithoutWallsAcrossTheLatticeAxes) {
  const TunnelMap diagonal = box_map(0.02, 0.6, 0.84, 1.2, Eigen::Vector3d(1.0, 1.0, 0.0).normalized());
  const Eigen::Vector3d o = wall_centred_origin(diagonal, Eigen::Matrix3d::Identity(), kVoxel);
  EXPECT_EQ(o.x(), 0.0);
  EXPECT_EQ(o.y(), 0.0);  // the side walls lie at 45 deg to both
  TunnelMap none;
  EXPECT_TRUE(wall_centred_origin(none, Eigen::Matrix3d::Identity(), kVoxel).isZero(0.0));
}
