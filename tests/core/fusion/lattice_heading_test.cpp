// The lattice's heading: fitted through the frames' centre points over a long stretch (good to
// thousandths of a degree), the merged map's axis over a short one, the world's axes near them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/fusion/lattice_heading.h"

using namespace tunnelmap;

namespace {

constexpr double kDeg = M_PI / 180.0;

// Detected maps every 0.2 m along a straight girder at `heading_deg` over `length_m`, each
// camera 0.3 m off the centre line with its own small error (1 mm) in where it puts the line.
struct Walk {
  std::vector<TunnelMap> maps;
  std::vector<Eigen::Isometry3d> poses;
  TunnelMap merged;

  Walk(double heading_deg, double length_m) {
    std::mt19937 rng(5);
    std::normal_distribution<double> mm(0.0, 0.001);
    const Eigen::Matrix3d yaw = Eigen::AngleAxisd(heading_deg * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (double s = 0.0; s <= length_m; s += 0.2) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = yaw;
      pose.translation() = yaw * Eigen::Vector3d(s, 0.3, 0.5);
      TunnelMap m;  // in the camera frame: the centre line 0.3 m to its right, seen 0.5-2.5 m ahead
      m.detected = true;
      m.axis_dir = Eigen::Vector3d::UnitX();
      const double across = mm(rng);  // drawn in order: argument order is the compiler's
      const double up = mm(rng);
      m.axis_point = Eigen::Vector3d(0.0, -0.3 + across, up);
      m.extent_min_m = 0.5;
      m.extent_max_m = 2.5;
      maps.push_back(m);
      poses.push_back(pose);
    }
    merged.detected = true;
    merged.axis_dir = yaw * Eigen::Vector3d(std::cos(0.2 * kDeg), std::sin(0.2 * kDeg), 0.0);  // averaged: 0.2 deg off
  }
  std::vector<PosedMap> posed() const {
    std::vector<PosedMap> out;
    for (std::size_t i = 0; i < maps.size(); ++i) out.push_back({&maps[i], poses[i]});
    return out;
  }
};

}  // namespace

TEST(LatticeHeading, FitsTheCentreLineOfALongWalk) {
  const Walk w(45.0, 30.0);
  const LatticeHeading h = lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(h.source, HeadingSource::CentreLine);
  // +45 and -45 deg turn the lattice onto the same planes.
  EXPECT_NEAR(std::remainder(h.yaw_deg - 45.0, 90.0), 0.0, 0.001);  // the merged axis alone is 0.2 deg off
  const Eigen::Vector3d x = h.lattice_to_world.col(0);
  EXPECT_NEAR(std::atan2(x.y(), x.x()) / kDeg, h.yaw_deg, 1e-9);
}

TEST(LatticeHeading, TurnsByTheHeadingOffTheNearestWorldAxis) {
  const Walk w(100.0, 30.0);  // 10 deg off the world's y
  const LatticeHeading h = lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(h.yaw_deg, 10.0, 0.001);
}

TEST(LatticeHeading, KeepsTheWorldAxesForAGirderAlongThem) {
  const Walk w(0.0, 30.0);
  const LatticeHeading h = lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(h.source, HeadingSource::CentreLine);
  EXPECT_TRUE(h.lattice_to_world.isIdentity(0.0));
  EXPECT_EQ(h.yaw_deg, 0.0);
}

TEST(LatticeHeading, AShortWalkUsesTheMergedAxis) {
  const Walk w(30.0, 3.0);  // under the 5 m baseline
  const LatticeHeading h = lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(h.source, HeadingSource::MergedAxis);
  EXPECT_NEAR(h.yaw_deg, 30.2, 1e-9);
}

TEST(LatticeHeading, WorldAxesWithoutAMapOrAVerticalUp) {
  Walk w(30.0, 30.0);
  EXPECT_TRUE(lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitY()).lattice_to_world.isIdentity(0.0));
  w.merged.detected = false;
  const LatticeHeading h = lattice_heading(w.posed(), w.merged, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(h.source, HeadingSource::World);
  EXPECT_TRUE(h.lattice_to_world.isIdentity(0.0));
}
