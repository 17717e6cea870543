// Frames that look back along the walk are mapped with the walk's left and right: turned round,
// they name the girder's walls as the frames looking ahead do.
#include "core/mapping/walk_facing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "core/evaluation/girder_scoring.h"
#include "core/tunnel/wall_geometry.h"
#include "tests/support/girder_walk_config.h"
#include "tests/support/mapped_girder.h"

namespace tunnelmap {
namespace {

// A frame's template in its camera frame: axis along the view from 0.6 m ahead over 3.5 m, the
// left wall at the camera's left (-x), up towards -y; walls 0.84 x 1.20 m, found and drawn.
TunnelMap frame_template() {
  TunnelMap m;
  m.detected = true;
  m.axis_dir = Eigen::Vector3d::UnitZ();
  m.up = -Eigen::Vector3d::UnitY();
  m.axis_point = Eigen::Vector3d(0.02, -0.10, 0.6);
  m.extent_min_m = 0.0;
  m.extent_max_m = 3.5;
  const double offsets[4] = {0.40, 0.44, 0.62, 0.58};
  for (int k = 0; k < 4; ++k) {
    m.walls[k].cls = static_cast<WallClass>(k);
    m.walls[k].found = true;
    m.walls[k].offset_m = offsets[k];
  }
  m.walls[0].normal = Eigen::Vector3d::UnitX();
  m.walls[1].normal = -Eigen::Vector3d::UnitX();
  m.walls[2].normal = Eigen::Vector3d::UnitY();
  m.walls[3].normal = -Eigen::Vector3d::UnitY();
  m.plane_classes = {WallClass::Left, WallClass::Top, WallClass::Right};
  m.plane_candidate_classes = {WallClass::Left, WallClass::Bottom};
  rebuild_wall_geometry(m, 0.1);
  return m;
}

Eigen::Matrix3d turned_about_up(double deg) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

TEST(WalkFacing, AFrameTurnedRoundLooksBackAndTheWalkFollowsACurve) {
  WalkFacing facing;
  const TunnelMap m = frame_template();
  EXPECT_FALSE(facing.looks_back(m, Eigen::Matrix3d::Identity()));  // the first sets the way
  EXPECT_TRUE(facing.looks_back(m, turned_about_up(175.0)));
  // A curve turns the walk by a few degrees per frame: 60 frames of 2 degrees each, never back.
  for (int k = 1; k <= 60; ++k) EXPECT_FALSE(facing.looks_back(m, turned_about_up(2.0 * k))) << k;
  EXPECT_TRUE(facing.looks_back(m, turned_about_up(120.0 + 180.0)));
  // A frame without a cross-section, or with an axis square to the walk, is not turned and
  // does not lead: the next frame looking back along the walk still is.
  TunnelMap none = m;
  none.detected = false;
  EXPECT_FALSE(facing.looks_back(none, turned_about_up(300.0)));
  EXPECT_FALSE(facing.looks_back(m, turned_about_up(120.0 + 80.0)));
  EXPECT_TRUE(facing.looks_back(m, turned_about_up(120.0 + 180.0)));
}

TEST(WalkFacing, TheWalkGoesTheWayTheFirstFrameLooksEvenWithoutACrossSection) {
  // The first frame faces a plate and finds no cross-section; the first that does looks back.
  WalkFacing facing;
  TunnelMap none = frame_template();
  none.detected = false;
  EXPECT_FALSE(facing.looks_back(none, Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(facing.looks_back(frame_template(), turned_about_up(178.0)));
}

TEST(WalkFacing, TurningRoundSwapsLeftAndRightOverTheSameStretchAndTwiceGivesTheFrameBack) {
  const TunnelMap original = frame_template();
  TunnelMap m = original;
  FrameWalls walls;
  walls.samples.resize(4);
  for (int k = 0; k < 3; ++k) walls.samples[k].wall = static_cast<std::uint8_t>(k);
  walls.samples[3].wall = kTransverseSample;
  turn_round(m, walls);
  EXPECT_EQ(m.axis_dir, -Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(m.axis_point.isApprox(original.axis_point + 3.5 * Eigen::Vector3d::UnitZ()));  // the far end
  EXPECT_DOUBLE_EQ(m.extent_min_m, 0.0);
  EXPECT_DOUBLE_EQ(m.extent_max_m, 3.5);
  // The camera's right wall is the walk's left, and the other way round; roof and floor stay.
  EXPECT_EQ(m.walls[0].cls, WallClass::Left);
  EXPECT_DOUBLE_EQ(m.walls[0].offset_m, 0.44);
  EXPECT_EQ(m.walls[0].normal, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(m.walls[1].cls, WallClass::Right);
  EXPECT_DOUBLE_EQ(m.walls[1].offset_m, 0.40);
  EXPECT_EQ(m.walls[1].normal, Eigen::Vector3d::UnitX());
  EXPECT_DOUBLE_EQ(m.walls[2].offset_m, 0.62);
  EXPECT_DOUBLE_EQ(m.walls[3].offset_m, 0.58);
  EXPECT_EQ(m.plane_classes, (std::vector<WallClass>{WallClass::Right, WallClass::Top, WallClass::Left}));
  EXPECT_EQ(m.plane_candidate_classes, (std::vector<WallClass>{WallClass::Right, WallClass::Bottom}));
  EXPECT_EQ(walls.samples[0].wall, 1);
  EXPECT_EQ(walls.samples[1].wall, 0);
  EXPECT_EQ(walls.samples[2].wall, 2);
  EXPECT_EQ(walls.samples[3].wall, kTransverseSample);
  // Walls drawn again while turned (the station map does so when it infers one) cover the same
  // stretch: turned back, the frame is as it was.
  rebuild_wall_geometry(m, 0.1);
  turn_round(m, walls);
  EXPECT_EQ(m.axis_dir, original.axis_dir);
  EXPECT_TRUE(m.axis_point.isApprox(original.axis_point));
  EXPECT_DOUBLE_EQ(m.extent_max_m, original.extent_max_m);
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(m.walls[k].offset_m, original.walls[k].offset_m) << k;
    // The same rectangle, its corners in another order.
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(), original_centre = Eigen::Vector3d::Zero();
    for (int c = 0; c < 4; ++c) centre += m.walls[k].boundary[c] / 4, original_centre += original.walls[k].boundary[c] / 4;
    EXPECT_TRUE(centre.isApprox(original_centre, 1e-9)) << k << ": " << centre.transpose();
  }
  EXPECT_EQ(m.plane_classes, original.plane_classes);
  EXPECT_EQ(walls.samples[0].wall, 0);
}

double worst(std::vector<double> v) {
  double w = 0.0;
  for (double x : v) w = std::max(w, std::abs(x));
  return w;
}

// 16 m, plates every 4 m, a stop every 0.5 m, drifting 10 mm and 0.2 degrees per square-root
// metre; the stops at 6, 10 and 13.5 m look back.
TEST(WalkFacing, AWalkThatLooksBackIsMappedWithTheWalksLeftAndRight) {
  SimConfig c = testing::girder_walk_config(16.0, 4.0, 31);
  c.drift_translation_mm_per_sqrt_m = 10.0;
  c.drift_rotation_deg_per_sqrt_m = 0.2;
  c.seed = 8;
  c.walk->look_back = true;
  const GirderScore s = testing::score_simulated_girder(c);
  std::printf("worst: width %.2f mm, height %.2f mm, across %.2f mm, pose %.2f mm, plate %.2f mm; plates %d of %zu\n",
              worst(s.width_error_mm), worst(s.height_error_mm), worst(s.pose_error_across_mm),
              worst(s.pose_error_mm), worst(s.plate_error_mm), s.plates_matched, s.plate_error_mm.size());
  // Named with the camera's left, the looks back put the girder's right wall on its left: a
  // station 1.7 m wide, and the walk pulled sideways by centimetres.
  EXPECT_LT(worst(s.width_error_mm), 5.0);
  EXPECT_LT(worst(s.height_error_mm), 5.0);
  EXPECT_LT(worst(s.pose_error_across_mm), 15.0);
  EXPECT_EQ(s.plates_invented, 0);
  EXPECT_LT(worst(s.plate_error_mm), 20.0);
  EXPECT_EQ(s.phantom_sections, 0);
}

}  // namespace
}  // namespace tunnelmap
