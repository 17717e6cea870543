// A wall's zones as layers: block samples go to the layer they lie on, whatever plane the
// segmentation grew over them.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "core/mapping/wall_zone_layers.h"

namespace tunnelmap {
namespace {

// A side wall 0.42 m to the camera's right (camera frame: x right, z forward), 1.2 m tall,
// seen from 0.5 to 4 m: edge bands (|y| > 0.45 m) on the outer surface, the middle plate
// `thickness` inside it. Each sample is the mean of 64 pixels whose depth has noise
// 2 mm z^2, moved along its ray.
struct Wall {
  std::vector<LayerSample> samples;
  std::vector<double> true_inset;
};

const Eigen::Vector3d kOutward = Eigen::Vector3d::UnitX(), kAxis = Eigen::Vector3d::UnitZ();

Wall wall_seen(double thickness, double far_m, std::mt19937& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  Wall w;
  for (double z = 0.5; z <= far_m; z += 0.05)
    for (double y = -0.58; y <= 0.58; y += 0.04) {
      const double inset = std::abs(y) > 0.45 ? 0.0 : thickness;
      const Eigen::Vector3d on_wall(0.42 - inset, y, z);
      const double sigma_depth = 0.002 * z * z / 8.0;
      LayerSample s;
      s.point = on_wall * (1.0 + unit(rng) * sigma_depth / z);
      s.sigma_m = sigma_depth * 0.42 / z;
      w.samples.push_back(s);
      w.true_inset.push_back(inset);
    }
  return w;
}

// The yaw of the plane through `samples` whose insets are `level` (degrees; the wall runs
// along z, so a tilt shows as the normal's z part).
double tilt_deg(const Wall& w, const std::vector<double>& insets, double level) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  int n = 0;
  for (std::size_t i = 0; i < insets.size(); ++i)
    if (std::abs(insets[i] - level) < 1e-6) {
      sum += w.samples[i].point;
      outer += w.samples[i].point * w.samples[i].point.transpose();
      ++n;
    }
  const Eigen::Vector3d mean = sum / n;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(outer / n - mean * mean.transpose());
  const Eigen::Vector3d normal = eig.eigenvectors().col(0);
  return std::asin(std::abs(normal.z())) * 180.0 / M_PI;
}

TEST(WallZoneLayers, SamplesOfAMergedPlaneGoBackToTheirZones) {
  // The segmentation grew the middle plate's plane over the edge bands beyond 1.5 m: the edge
  // bands' share grows with the distance, so that plane tilts, and its inset lies between the
  // zones'. The layers put each sample back where it lies, and neither zone tilts.
  std::mt19937 rng(11);
  Wall w = wall_seen(0.006, 3.5, rng);
  for (std::size_t i = 0; i < w.samples.size(); ++i)
    w.samples[i].inset_m = w.samples[i].point.z() > 1.5 || w.true_inset[i] > 0.0 ? 0.005 : 0.0;
  std::vector<double> merged;
  for (const LayerSample& s : w.samples) merged.push_back(s.inset_m);
  EXPECT_GT(tilt_deg(w, merged, 0.005), 0.02);  // what the merged plane did

  const std::vector<double> insets = wall_zone_layers(w.samples, kOutward, kAxis);
  int placed = 0, wrong = 0;
  for (std::size_t i = 0; i < insets.size(); ++i) {
    if (std::isnan(insets[i])) continue;
    ++placed;
    if (std::abs(insets[i] - w.true_inset[i]) > 0.0015) ++wrong;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(placed, static_cast<int>(0.9 * insets.size()));
  EXPECT_LT(tilt_deg(w, insets, insets[0]), 0.005);  // the first sample: an edge band
}

TEST(WallZoneLayers, ABlockAcrossAZonesEdgeIsLeftOut) {
  // Half its pixels on the edge band, half on the middle plate: 3 mm inside, on neither.
  std::mt19937 rng(5);
  Wall w = wall_seen(0.008, 2.0, rng);
  for (std::size_t i = 0; i < w.samples.size(); ++i) w.samples[i].inset_m = w.true_inset[i];
  LayerSample edge;
  edge.point = Eigen::Vector3d(0.416, 0.45, 1.2);
  edge.sigma_m = 0.0002;
  edge.inset_m = 0.0;
  w.samples.push_back(edge);
  const std::vector<double> insets = wall_zone_layers(w.samples, kOutward, kAxis);
  EXPECT_TRUE(std::isnan(insets.back()));
}

TEST(WallZoneLayers, SamplesTooNoisyToTellTheZonesApartAreLeftOut) {
  std::mt19937 rng(7);
  Wall w = wall_seen(0.006, 2.0, rng);
  for (std::size_t i = 0; i < w.samples.size(); ++i) w.samples[i].inset_m = w.true_inset[i];
  w.samples.front().sigma_m = 0.002;  // a third of the step
  const std::vector<double> insets = wall_zone_layers(w.samples, kOutward, kAxis);
  EXPECT_TRUE(std::isnan(insets.front()));
  EXPECT_FALSE(std::isnan(insets[1]));
}

TEST(WallZoneLayers, ZonesTheSamplesPutCloserThanAPlateAreOne) {
  // The frame took two planes of one wall for two zones 2.6 mm apart; the samples put them
  // 1.8 mm apart (a plate bent by its welds), closer than any plate is thick. Kept as two, the
  // far plane's samples would go to a zone apart from the near one's, and their noise be cut
  // between the two; they are one zone.
  std::mt19937 rng(9);
  Wall w = wall_seen(0.0, 3.0, rng);
  for (LayerSample& s : w.samples) {
    const bool far = s.point.z() >= 1.5;
    s.inset_m = far ? 0.0026 : 0.0;
    if (far) s.point.x() -= 0.0018;
  }
  const std::vector<double> insets = wall_zone_layers(w.samples, kOutward, kAxis);
  for (double inset : insets) EXPECT_DOUBLE_EQ(inset, insets.front());
  EXPECT_FALSE(std::isnan(insets.front()));
}

TEST(WallZoneLayers, AWallOfOneZoneKeepsItsPlanesInsets) {
  std::mt19937 rng(3);
  Wall w = wall_seen(0.0, 4.0, rng);
  for (LayerSample& s : w.samples) {
    s.inset_m = 0.0004;
    s.sigma_m = 0.01;  // however noisy: nothing to tell apart
  }
  const std::vector<double> insets = wall_zone_layers(w.samples, kOutward, kAxis);
  for (double inset : insets) EXPECT_DOUBLE_EQ(inset, 0.0004);
}

}  // namespace
}  // namespace tunnelmap
