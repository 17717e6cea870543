// What one frame's plate contributes to the pose graph: its weight against the depth's
// quantisation, with and without the noise that dithers it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/mapping/slam_patches.h"

namespace tunnelmap {
namespace {

// A structured-light camera's disparity: fx 570.3 px, baseline 75 mm, 1/8 pixel steps
// (2.9 mm at 1 m, 59 mm at 4.5 m), as slam.depth_step_mm assumes.
constexpr double kFxB = 570.3 * 0.075, kSteps = 8.0;

double quantised(double z) { return kFxB / (std::round(kFxB * kSteps / z) / kSteps); }

// A plate facing the camera at `depth`, 0.4 x 0.6 m, seen as 8 x 8 blocks of pixels whose depth
// gets noise `sigma_at_1m` z^2 before it is rounded to the camera's steps.
FrameWalls plate_at(double depth, double sigma_at_1m, std::mt19937& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  FrameWalls walls;
  for (double x = -0.2; x <= 0.2; x += 0.04)
    for (double y = -0.3; y <= 0.3; y += 0.04) {
      const Eigen::Vector3d ray(x / depth, y / depth, 1.0);
      double sum = 0.0;
      for (int k = 0; k < 64; ++k) sum += quantised(depth + unit(rng) * sigma_at_1m * depth * depth);
      WallSample s;
      s.point = (ray * (sum / 64.0)).cast<float>();
      s.points = 64;
      s.plane = 7;
      s.wall = kTransverseSample;
      walls.samples.push_back(s);
    }
  return walls;
}

FramePatch plate_patch(const FrameWalls& walls) {
  const std::vector<FramePatch> patches =
      frame_patches(TunnelMap(), walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions());
  EXPECT_EQ(patches.size(), 1u);
  return patches.empty() ? FramePatch() : patches.front();
}

TEST(SlamPatches, APlateOnOneDepthStepKeepsThatStepsError) {
  // Without noise every pixel rounds to the same step: the plate is off by up to half a step,
  // whatever the number of pixels, and its weight says so.
  std::mt19937 rng(3);
  const double depth = 4.47, step = depth * depth / (kFxB * kSteps);
  const FramePatch p = plate_patch(plate_at(depth, 0.0, rng));
  EXPECT_GT(p.sigma_m, 0.95 * step / std::sqrt(12.0));
  EXPECT_LT(std::abs(p.centroid.z() - depth), 0.5 * step + 1e-6);
}

TEST(SlamPatches, NoiseBeforeTheRoundingAveragesTheStepsAway) {
  // The depth noise of the evaluation's cameras is about half a step at every depth (both grow
  // with z^2): the mean of many rounded pixels lies within a few millimetres of the plate at
  // 4.5 m, where a step is 59 mm, and the patch is weighted for that (its calibration floor,
  // 6 mm there, is what is left), not for a whole step.
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    const double depth = 4.0 + 0.025 * seed;
    const FramePatch p = plate_patch(plate_at(depth, 0.0015, rng));
    const double step = depth * depth / (kFxB * kSteps);
    EXPECT_LT(std::abs(p.centroid.z() - depth), 0.05 * step) << depth;
    EXPECT_LT(p.sigma_m, 0.4 * step / std::sqrt(12.0)) << depth;
  }
}

}  // namespace
}  // namespace tunnelmap
