// The rectangular template: the tunnel frame from the four class mean normals (inward), the
// antiparallel and perpendicular checks with their statuses, and the partial template from the
// walls in view.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "core/tunnel/normal_outliers.h"
#include "core/tunnel/template_fit.h"

namespace tunnelmap {
namespace {

// Camera frame: x right, y down, z forward. A level camera in a straight tunnel sees the left
// wall facing +x, the right wall -x, the roof facing down (+y) and the floor up (-y).
const Eigen::Vector3d kLeft(1, 0, 0), kRight(-1, 0, 0), kTop(0, 1, 0), kBottom(0, -1, 0);
const Eigen::Vector3d kForward(0, 0, 1);

Eigen::Vector3d rotated(const Eigen::Vector3d& v, double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(deg * M_PI / 180.0, axis.normalized()) * v;
}

TEST(TemplateFit, PerfectRectangleGivesTheCameraAxesExactly) {
  const TemplateFrame t = fit_rectangular_template(kLeft, kRight, kTop, kBottom, kForward, 3.0);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.status, TunnelStatus::Ok);
  EXPECT_TRUE(t.reason.empty());
  EXPECT_LT((t.right - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((t.up - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
  EXPECT_LT((t.axis - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);
  EXPECT_NEAR(t.left_right_angle_deg, 0.0, 1e-9);
  EXPECT_NEAR(t.top_bottom_angle_deg, 0.0, 1e-9);
  EXPECT_NEAR(t.pair_angle_deg, 0.0, 1e-9);
}

TEST(TemplateFit, AxisPointsAwayFromTheCamera) {
  // Looking back down the tunnel: the same walls, camera forward -z.
  const TemplateFrame t = fit_rectangular_template(kLeft, kRight, kTop, kBottom, -kForward, 3.0);
  ASSERT_TRUE(t.ok);
  EXPECT_LT((t.axis - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  EXPECT_NEAR(t.axis.dot(t.up.cross(t.right)), -1.0, 1e-12);  // flipped, still unit
}

TEST(TemplateFit, WallsFiveDegreesFromParallelAreNoParallelPair) {
  const Eigen::Vector3d right = rotated(kRight, 5.0, Eigen::Vector3d::UnitY());
  const TemplateFrame t = fit_rectangular_template(kLeft, right, kTop, kBottom, kForward, 3.0);
  EXPECT_FALSE(t.ok);
  EXPECT_EQ(t.status, TunnelStatus::NoParallelPair);
  EXPECT_NEAR(t.left_right_angle_deg, 5.0, 1e-9);
  EXPECT_EQ(t.reason, "left and right walls are 5.0 deg from parallel (max 3.0)");
  // 2.5 deg is within the 3 deg limit.
  EXPECT_TRUE(fit_rectangular_template(kLeft, rotated(kRight, 2.5, Eigen::Vector3d::UnitY()), kTop, kBottom,
                                       kForward, 3.0).ok);
}

TEST(TemplateFit, PairsTenDegreesFromPerpendicularAreNotRectangular) {
  // Roof and floor turned 10 deg about the tunnel axis: each pair is antiparallel, the pairs
  // meet at 80 deg.
  const Eigen::Vector3d top = rotated(kTop, 10.0, kForward), bottom = rotated(kBottom, 10.0, kForward);
  const TemplateFrame t = fit_rectangular_template(kLeft, kRight, top, bottom, kForward, 3.0);
  EXPECT_FALSE(t.ok);
  EXPECT_EQ(t.status, TunnelStatus::NotRectangular);
  EXPECT_NEAR(t.pair_angle_deg, 10.0, 1e-9);
  EXPECT_EQ(t.reason, "wall pairs are 10.0 deg from perpendicular (max 3.0)");
}

TEST(TemplateFit, SlightlySkewedPairsShareTheSkewEqually) {
  // Pairs 88 deg apart (within 3): the frame is orthonormal and each axis 1 deg from its pair.
  const Eigen::Vector3d top = rotated(kTop, 2.0, kForward), bottom = rotated(kBottom, 2.0, kForward);
  const TemplateFrame t = fit_rectangular_template(kLeft, kRight, top, bottom, kForward, 3.0);
  ASSERT_TRUE(t.ok);
  EXPECT_NEAR(t.pair_angle_deg, 2.0, 1e-9);
  EXPECT_NEAR(t.right.dot(t.up), 0.0, 1e-12);
  EXPECT_NEAR(angle_deg(t.right, kLeft), 1.0, 1e-9);
  EXPECT_NEAR(angle_deg(t.up, bottom), 1.0, 1e-9);
  EXPECT_LT((t.axis - kForward).norm(), 1e-12);
}

TEST(TemplateFit, OneWallOutOfViewTakesItsPairFromTheOtherWall) {
  // Right wall not seen, left wall 2 deg off the camera's x axis (about the axis): "right" is
  // the left wall's normal exactly; roof and floor still fix "up".
  const Eigen::Vector3d left = rotated(kLeft, 2.0, kForward);
  const Eigen::Vector3d top = rotated(kTop, 2.0, kForward), bottom = rotated(kBottom, 2.0, kForward);
  const Eigen::Vector3d means[4] = {left, Eigen::Vector3d::Zero(), top, bottom};
  const bool seen[4] = {true, false, true, true};
  TemplateFrame t;
  fit_partial_template(means, seen, kLeft, kBottom, kForward, 3.0, t);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.status, TunnelStatus::Ok);
  EXPECT_LT((t.right - left).norm(), 1e-12);
  EXPECT_LT((t.up - bottom).norm(), 1e-12);
  EXPECT_NEAR(t.left_right_angle_deg, 0.0, 1e-12);  // no pair to compare
}

TEST(TemplateFit, OnlyOnePairInViewTakesTheOtherDirectionFromTheRoughFrame) {
  // Left and right walls only; the rough "up" is 5 deg off perpendicular to them and is made
  // perpendicular.
  const Eigen::Vector3d means[4] = {kLeft, kRight, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  const bool seen[4] = {true, true, false, false};
  const Eigen::Vector3d rough_up = rotated(kBottom, 5.0, kForward);
  TemplateFrame t;
  fit_partial_template(means, seen, kLeft, rough_up, kForward, 3.0, t);
  ASSERT_TRUE(t.ok);
  EXPECT_LT((t.right - kLeft).norm(), 1e-12);
  EXPECT_LT((t.up - kBottom).norm(), 1e-12);
  EXPECT_LT((t.axis - kForward).norm(), 1e-12);
  // A seen pair that is not antiparallel is still refused.
  const Eigen::Vector3d skewed[4] = {kLeft, rotated(kRight, 4.0, kBottom), Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero()};
  fit_partial_template(skewed, seen, kLeft, rough_up, kForward, 3.0, t);
  EXPECT_FALSE(t.ok);
  EXPECT_EQ(t.status, TunnelStatus::NoParallelPair);
  EXPECT_NEAR(t.left_right_angle_deg, 4.0, 1e-9);
}

TEST(TemplateFit, APairFollowsItsBetterSupportedWall) {
  // A roof of 30,000 points and a floor sliver of 700 points pitched 1.2 deg from it (about
  // the camera's x axis): weighted by points, "up" stays within 0.05 deg of the roof; the plain
  // mean of the two would split the difference (0.6 deg).
  const Eigen::Vector3d bottom = rotated(kBottom, 1.2, kLeft);
  const Eigen::Vector3d means[4] = {kLeft, kRight, kTop, bottom};
  const bool seen[4] = {true, true, true, true};
  const double weights[4] = {20000, 20000, 30000, 700};
  TemplateFrame t;
  fit_partial_template(means, seen, kLeft, kBottom, kForward, 3.0, t, weights);
  ASSERT_TRUE(t.ok);
  EXPECT_LT(angle_deg(t.up, -kTop), 0.05);
  EXPECT_NEAR(angle_deg(t.right, kLeft), 0.0, 1e-9);
  fit_partial_template(means, seen, kLeft, kBottom, kForward, 3.0, t);
  EXPECT_NEAR(angle_deg(t.up, -kTop), 0.6, 1e-3);
}

}  // namespace
}  // namespace tunnelmap
