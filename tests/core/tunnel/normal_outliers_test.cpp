// Normal outlier rejection of one wall class: the robust seed, the histogram of angular
// deviations (bins of bin_deg, cut at the first empty bin after the peak, never beyond
// max_deg) and the weighted Gaussian statistics of the inliers.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/tunnel/normal_outliers.h"

namespace tunnelmap {
namespace {

// The unit vector `deg` degrees from +Z, leaning towards azimuth `azimuth_deg` (0 = +X, 90 = +Y).
Eigen::Vector3d off_z(double deg, double azimuth_deg = 0.0) {
  const double t = deg * M_PI / 180.0, a = azimuth_deg * M_PI / 180.0;
  return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

TEST(NormalOutliers, AngleIsExactForTinyAndRightAngles) {
  EXPECT_NEAR(angle_deg(Eigen::Vector3d::UnitZ(), off_z(1e-4)), 1e-4, 1e-12);
  EXPECT_NEAR(angle_deg(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()), 90.0, 1e-12);
  EXPECT_NEAR(angle_deg(Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()), 180.0, 1e-12);
}

TEST(NormalOutliers, NoNormalsIsNotValid) {
  const NormalClassStats s = reject_normal_outliers({}, 1.0, 20.0);
  EXPECT_FALSE(s.valid);
  EXPECT_TRUE(s.inlier.empty());
}

TEST(NormalOutliers, PlaneBeyondMaxDegIsRejected) {
  // Four planes within 1 deg of +Z and one 25 deg off; max 20 deg.
  const std::vector<WeightedNormal> normals = {
      {off_z(0.5, 0), 100}, {off_z(0.5, 90), 100}, {off_z(0.5, 180), 100}, {off_z(0.5, 270), 100}, {off_z(25.0), 100}};
  const NormalClassStats s = reject_normal_outliers(normals, 1.0, 20.0);
  ASSERT_TRUE(s.valid);
  EXPECT_EQ(s.inlier, (std::vector<bool>{true, true, true, true, false}));
  // The four inliers are symmetric about +Z: their mean is +Z, each 0.5 deg from it.
  EXPECT_NEAR(angle_deg(s.mean, Eigen::Vector3d::UnitZ()), 0.0, 1e-9);
  EXPECT_NEAR(s.sd_deg, 0.5, 1e-9);
}

TEST(NormalOutliers, PlaneAfterAnEmptyBinIsRejectedWithinMaxDeg) {
  // 1 deg bins: inliers fill bins 0 and 1; a plane at 6 deg sits after empty bins 2..5, so the
  // main mode has ended although 6 < max 20.
  const std::vector<WeightedNormal> normals = {{off_z(0.2), 50}, {off_z(1.4, 180), 50}, {off_z(6.0, 90), 10}};
  const NormalClassStats s = reject_normal_outliers(normals, 1.0, 20.0);
  ASSERT_TRUE(s.valid);
  EXPECT_EQ(s.inlier, (std::vector<bool>{true, true, false}));
}

TEST(NormalOutliers, PlaneInTheBinNextToThePeakIsKept) {
  // The same plane at 1.8 deg: bin 1, next to the peak bin 0, so part of the main mode.
  const std::vector<WeightedNormal> normals = {{off_z(0.2), 50}, {off_z(0.4, 180), 50}, {off_z(1.8, 90), 10}};
  const NormalClassStats s = reject_normal_outliers(normals, 1.0, 20.0);
  ASSERT_TRUE(s.valid);
  EXPECT_EQ(s.inlier, (std::vector<bool>{true, true, true}));
}

TEST(NormalOutliers, MeanAndSpreadAreWeightedByPointCount) {
  // +1 deg with weight 3 and -1 deg with weight 1 (both in the x-z plane): the weighted sum
  // points at atan(0.5 tan 1 deg) = 0.50002 deg; the RMS deviation is
  // sqrt((3 * 0.49998^2 + 1 * 1.50002^2) / 4) = 0.86603 deg.
  const std::vector<WeightedNormal> normals = {{off_z(1.0, 0), 3}, {off_z(1.0, 180), 1}};
  const NormalClassStats s = reject_normal_outliers(normals, 1.0, 20.0);
  ASSERT_TRUE(s.valid);
  const double expected = std::atan(0.5 * std::tan(M_PI / 180.0)) * 180.0 / M_PI;
  EXPECT_NEAR(angle_deg(s.mean, off_z(expected, 0)), 0.0, 1e-9);
  const double a = 1.0 - expected, b = 1.0 + expected;
  EXPECT_NEAR(s.sd_deg, std::sqrt((3 * a * a + b * b) / 4.0), 1e-9);
  EXPECT_NEAR(s.sd_deg, 0.86603, 1e-5);
  EXPECT_NEAR(s.mean.norm(), 1.0, 1e-12);
}

TEST(NormalOutliers, DenseClusterWinsOverScatteredOutliersOfEqualCount) {
  // Five planes within 1 deg of +Z and five scattered 30..60 deg away in different directions:
  // a plain mean would be dragged about 20 deg; the mode-seeking seed is not.
  std::vector<WeightedNormal> normals;
  for (int k = 0; k < 5; ++k) normals.push_back({off_z(0.8, 72.0 * k), 20});
  for (int k = 0; k < 5; ++k) normals.push_back({off_z(30.0 + 7.5 * k, 36.0 + 72.0 * k), 20});
  const NormalClassStats s = reject_normal_outliers(normals, 1.0, 15.0);
  ASSERT_TRUE(s.valid);
  for (int k = 0; k < 10; ++k) EXPECT_EQ(s.inlier[k], k < 5) << k;
  EXPECT_NEAR(angle_deg(s.mean, Eigen::Vector3d::UnitZ()), 0.0, 1e-9);
  EXPECT_NEAR(s.sd_deg, 0.8, 1e-9);
}

}  // namespace
}  // namespace tunnelmap
