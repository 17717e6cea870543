// Wall classification: the rough tunnel frame from "up" and the camera's view direction, and the
// class cone around each wall's inward normal.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/tunnel/wall_classification.h"

namespace tunnelmap {
namespace {

// A level camera (x right, y down, z forward): up is -y.
const Eigen::Vector3d kUp(0, -1, 0);

Eigen::Vector3d rotated(const Eigen::Vector3d& v, double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, axis.normalized()) * v;
}

TEST(WallClassification, LevelCameraFrameIsTheCameraAxes) {
  const RoughTunnelFrame f = make_rough_frame(Eigen::Vector3d(0, -2, 0));  // normalised here
  EXPECT_LT((f.up - kUp).norm(), 1e-12);
  EXPECT_LT((f.forward - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);
  EXPECT_LT((f.right - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
}

TEST(WallClassification, PitchedCameraKeepsForwardLevel) {
  // Camera pitched 20 deg: "up" is no longer -y; forward is camera +z with its up part removed.
  const Eigen::Vector3d up = rotated(kUp, 20.0, Eigen::Vector3d::UnitX());
  const RoughTunnelFrame f = make_rough_frame(up);
  EXPECT_NEAR(f.forward.dot(f.up), 0.0, 1e-12);
  EXPECT_NEAR(f.forward.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::acos(f.forward.dot(Eigen::Vector3d::UnitZ())) * 180.0 / M_PI, 20.0, 1e-9);
  EXPECT_LT((f.right - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((f.right - f.forward.cross(f.up)).norm(), 1e-12);
}

TEST(WallClassification, CameraLookingAlongUpFallsBackOnCameraX) {
  const RoughTunnelFrame f = make_rough_frame(Eigen::Vector3d(0, 0, 1));
  EXPECT_LT((f.right - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((f.forward - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);
}

TEST(WallClassification, EachWallsInwardNormalGivesItsClass) {
  const RoughTunnelFrame f = make_rough_frame(kUp);
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(0, 1, 0), 30.0), WallClass::Top);      // roof faces down
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(0, -1, 0), 30.0), WallClass::Bottom);  // floor faces up
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(1, 0, 0), 30.0), WallClass::Left);     // left wall faces right
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(-1, 0, 0), 30.0), WallClass::Right);
  // Facing the camera (a plate across the tunnel): no wall.
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(0, 0, -1), 30.0), WallClass::Unassigned);
  // Length does not matter.
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(-3, 0, 0), 30.0), WallClass::Right);
}

TEST(WallClassification, NormalInsideTheConeJoinsAndBeyondDoesNot) {
  // Cone of 30 deg about each class direction, tilted towards the camera (about the other axis).
  const RoughTunnelFrame f = make_rough_frame(kUp);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(classify_normal(f, rotated(Eigen::Vector3d(0, 1, 0), 29.5, Eigen::Vector3d::UnitX()), 30.0), WallClass::Top);
  EXPECT_EQ(classify_normal(f, rotated(Eigen::Vector3d(0, 1, 0), 30.5, Eigen::Vector3d::UnitX()), 30.0),
            WallClass::Unassigned);
  EXPECT_EQ(classify_normal(f, rotated(Eigen::Vector3d(1, 0, 0), 29.5, z), 30.0), WallClass::Left);
  EXPECT_EQ(classify_normal(f, rotated(Eigen::Vector3d(1, 0, 0), 30.5, z), 30.0), WallClass::Unassigned);
  // 40 deg off the left wall's direction (and 50 off the roof's): inside a 45 deg cone only.
  const Eigen::Vector3d between = rotated(Eigen::Vector3d(1, 0, 0), 40.0, z);
  EXPECT_EQ(classify_normal(f, between, 30.0), WallClass::Unassigned);
  EXPECT_EQ(classify_normal(f, between, 45.0), WallClass::Left);
}

TEST(WallClassification, ZeroAndNonFiniteNormalsAreUnassigned) {
  const RoughTunnelFrame f = make_rough_frame(kUp);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d::Zero(), 45.0), WallClass::Unassigned);
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(nan, 1, 0), 45.0), WallClass::Unassigned);
  EXPECT_EQ(classify_normal(f, Eigen::Vector3d(0, std::numeric_limits<double>::infinity(), 0), 45.0),
            WallClass::Unassigned);
}

TEST(WallClassification, ClassifyPlanesKeepsThePlanesOrder) {
  PlaneSegments planes;
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(-1, 0, 0),
                                   Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0)}) {
    planes.planes.emplace_back();
    planes.planes.back().normal = n;
  }
  const std::vector<WallClass> classes = classify_planes(make_rough_frame(kUp), planes, 30.0);
  EXPECT_EQ(classes, (std::vector<WallClass>{WallClass::Bottom, WallClass::Unassigned, WallClass::Right,
                                             WallClass::Top, WallClass::Left}));
}

}  // namespace
}  // namespace tunnelmap
