// What one frame contributes to the pose graph: a plate's weight against the depth's
// quantisation, with and without the noise that dithers it; a frame without a cross-section's
// plates; a wall's zones, apart, whatever planes the segmentation grew over them; a wall band
// cut at the plate where the wall kinks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/mapping/slam_patches.h"

namespace tunnelmap {
namespace {

const WallBandGrid kOneMetreBands(1.0, {});

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
      frame_plate_patches(TunnelMap(), walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions());
  EXPECT_EQ(patches.size(), 1u);
  return patches.empty() ? FramePatch() : patches.front();
}

TEST(SlamPatches, AFrameWithoutACrossSectionKeepsOnlyPlatesAcrossTheGirdersAxis) {
  // A frame that found no cross-section chose its plates by the camera's forward direction; the
  // girder's axis (its group's) decides. A plane 40 degrees off the axis is no plate across it.
  std::mt19937 rng(5);
  const FrameWalls walls = plate_at(1.2, 0.0, rng);  // facing the camera: normal along +Z
  const Eigen::Vector3d tilted_axis(std::sin(40.0 * M_PI / 180.0), 0.0, std::cos(40.0 * M_PI / 180.0));
  const Eigen::Vector3d near_axis(std::sin(10.0 * M_PI / 180.0), 0.0, std::cos(10.0 * M_PI / 180.0));
  const TunnelMap undetected;
  ASSERT_FALSE(undetected.detected);
  EXPECT_TRUE(frame_plate_patches(undetected, walls, 0.0, tilted_axis, SlamOptions()).empty());
  EXPECT_EQ(frame_plate_patches(undetected, walls, 0.0, near_axis, SlamOptions()).size(), 1u);
  // A frame's own detection chose them by its own axis: kept as it gives them.
  TunnelMap detected;
  detected.detected = true;
  EXPECT_EQ(frame_plate_patches(detected, walls, 0.0, tilted_axis, SlamOptions()).size(), 1u);
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

TEST(SlamPatches, APlateTheRangeCutIsLeftOutOfTheGraphAndOfTheStationMapAlike) {
  // Depth beyond 5 m is dropped pixel by pixel: a plate at 4.9 m with 36 mm of noise per pixel
  // keeps its nearer pixels and comes out too near. At 4 m (24 mm) its farthest block lies
  // three sigmas inside the range.
  std::mt19937 rng(5);
  SlamOptions o;
  o.cloud_max_range_m = 5.0;
  FrameWalls walls = plate_at(4.0, 0.0015, rng);
  FrameWalls far = plate_at(4.9, 0.0015, rng);
  for (WallSample& s : far.samples) s.plane = 8;
  walls.samples.insert(walls.samples.end(), far.samples.begin(), far.samples.end());
  EXPECT_EQ(plates_cut_by_range(walls, o.cloud_max_range_m, o.point_sigma_m), std::vector<int>{8});
  const std::vector<FramePatch> patches = frame_plate_patches(TunnelMap(), walls, 0.0, Eigen::Vector3d::UnitZ(), o);
  ASSERT_EQ(patches.size(), 1u);
  EXPECT_NEAR(patches[0].centroid.z(), 4.0, 0.02);
  // No range, no cut.
  EXPECT_TRUE(plates_cut_by_range(walls, INFINITY, o.point_sigma_m).empty());
}

// The right wall of a 0.84 m girder seen along it (camera frame: x right, z forward) from 0.6
// to 3.6 m: edge bands above and below on the outer surface, the middle plate 6 mm inside.
// The segmentation kept the near edge bands apart and grew the middle plate's plane over the
// far ones (the inset it reports lies between the zones'), as it does where the pixels'
// noise is as large as the step.
FrameWalls merged_zones(TunnelMap& map) {
  map.walls[1].normal = -Eigen::Vector3d::UnitX();
  map.walls[1].offset_m = 0.42;
  std::mt19937 rng(2);
  std::normal_distribution<double> unit(0.0, 1.0);
  FrameWalls walls;
  for (double z = 0.6; z <= 3.6; z += 0.04)
    for (double y = -0.56; y <= 0.56; y += 0.04) {
      const bool edge_band = std::abs(y) > 0.45;
      const Eigen::Vector3d on_wall(edge_band ? 0.42 : 0.414, y, z);
      WallSample s;
      s.point = (on_wall * (1.0 + unit(rng) * 0.002 * z / 8.0)).cast<float>();
      s.points = 64;
      s.wall = 1;
      s.plane = edge_band && z < 1.5 ? 1 : 2;
      s.inset_m = s.plane == 1 ? 0.0f : 0.005f;
      walls.samples.push_back(s);
    }
  return walls;
}

TEST(SlamPatches, AWallsZonesStayApartWhereTheSegmentationMergedThem) {
  // Each band of the wall gives one patch per zone, on that zone: the middle plate's lie 6 mm
  // inside, the edge bands' on the outer surface, and none is tilted by the other zone's
  // share (a tilt of 0.01 deg moves a patch 0.5 mm over 3 m).
  TunnelMap map;
  const FrameWalls walls = merged_zones(map);
  int middle = 0, edge = 0;
  for (const FramePatch& p : frame_wall_patches(map, walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), kOneMetreBands)) {
    ASSERT_FALSE(p.plate);
    const bool inner = p.zone == FramePatch::Zone::Inner;
    (inner ? middle : edge) += 1;
    EXPECT_NEAR(p.centroid.x(), inner ? 0.414 : 0.42, 0.0005) << p.band;
    const Eigen::Vector3d normal = p.spread.col(0).cross(p.spread.col(1)).normalized();
    EXPECT_LT(std::asin(std::abs(normal.z())) * 180.0 / M_PI, 0.01) << p.band << (inner ? " middle" : " edge");
  }
  EXPECT_EQ(middle, 4);  // bands 0-3
  EXPECT_EQ(edge, 4);
}

TEST(SlamPatches, PartsOfAFrameWhoseWallDoesNotStepAreOneWall) {
  // The frame split its view at 2 m where its section only seemed to change (it does so at a
  // sixth of the frames of a girder of one section): the wall's zones are fitted as one, and
  // every patch is what it is without the split.
  TunnelMap map;
  const FrameWalls whole = merged_zones(map);
  FrameWalls split = whole;
  for (WallSample& s : split.samples) s.part = s.point.z() >= 2.0f ? 1 : 0;
  const std::vector<FramePatch> a = frame_wall_patches(map, whole, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), kOneMetreBands);
  const std::vector<FramePatch> b = frame_wall_patches(map, split, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), kOneMetreBands);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].points, b[k].points);
    EXPECT_LT((a[k].centroid - b[k].centroid).norm(), 1e-9);
  }
}

TEST(SlamPatches, EachCrossSectionsWallHasItsOwnZones) {
  // The same wall, 20 mm narrower from 2 m on (a joint in view, the frame's second part): its
  // zones lie 20 mm further in there. Each part's samples go to that part's zones, all of
  // them, on their own layer.
  TunnelMap map;
  map.walls[1].normal = -Eigen::Vector3d::UnitX();
  map.walls[1].offset_m = 0.42;
  FrameWalls walls;
  for (double z = 0.6; z <= 3.6; z += 0.04)
    for (double y = -0.56; y <= 0.56; y += 0.04) {
      const bool edge_band = std::abs(y) > 0.45, beyond = z >= 2.0;
      WallSample s;
      s.point = Eigen::Vector3f((edge_band ? 0.42f : 0.414f) - (beyond ? 0.02f : 0.0f), y, z);
      s.points = 64;
      s.wall = 1;
      s.plane = (edge_band ? 1 : 2) + (beyond ? 2 : 0);
      s.inset_m = edge_band ? 0.0f : 0.006f;
      s.part = beyond ? 1 : 0;
      walls.samples.push_back(s);
    }
  int patches = 0, points = 0;
  for (const FramePatch& p : frame_wall_patches(map, walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), kOneMetreBands)) {
    const bool inner = p.zone == FramePatch::Zone::Inner, beyond = p.centroid.z() >= 2.0;
    EXPECT_NEAR(p.centroid.x(), (inner ? 0.414 : 0.42) - (beyond ? 0.02 : 0.0), 1e-4) << p.band;
    ++patches;
    points += p.points;
  }
  EXPECT_EQ(patches, 8);  // bands 0-3, two zones each
  EXPECT_EQ(points, 64 * static_cast<int>(walls.samples.size()));
}

// The right wall of a chorded girder on a curve, seen along it: straight to the plate at 2.4 m,
// then turned 1.5 degrees (a 150 m radius, plates 4 m apart).
FrameWalls wall_kinked_at(double plate_m, double kink_deg, TunnelMap& map) {
  map.walls[1].normal = -Eigen::Vector3d::UnitX();
  map.walls[1].offset_m = 0.42;
  FrameWalls walls;
  const double slope = std::tan(kink_deg * M_PI / 180.0);
  for (double z = 0.6; z <= 3.6; z += 0.02)
    for (double y = -0.4; y <= 0.4; y += 0.04) {
      WallSample s;
      s.point = Eigen::Vector3f(static_cast<float>(0.42 + std::max(0.0, z - plate_m) * slope), static_cast<float>(y),
                                static_cast<float>(z));
      s.points = 64;
      s.wall = 1;
      s.plane = 1;
      walls.samples.push_back(s);
    }
  return walls;
}

double tilt_deg(const FramePatch& p) {  // of the patch's plane about the camera's y, from the wall's
  const Eigen::Vector3d normal = p.spread.col(0).cross(p.spread.col(1)).normalized();
  return std::atan2(-normal.z(), std::abs(normal.x())) * 180.0 / M_PI * (normal.x() < 0 ? -1.0 : 1.0);
}

TEST(SlamPatches, AWallBandIsCutAtThePlateWhereTheWallKinks) {
  TunnelMap map;
  const FrameWalls walls = wall_kinked_at(2.4, 1.5, map);
  const WallBandGrid cut(1.0, {2.4});
  int before = 0, past = 0;
  for (const FramePatch& p : frame_wall_patches(map, walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), cut)) {
    const bool is_past = cut.from_m(p.band) >= 2.4;
    (is_past ? past : before) += 1;
    EXPECT_NEAR(std::abs(tilt_deg(p)), is_past ? 1.5 : 0.0, 0.01) << cut.from_m(p.band);
  }
  EXPECT_EQ(before, 2);  // 0.6-1, 1-2.4 (2-2.4 alone would be short)
  EXPECT_EQ(past, 2);    // 2.4-3, 3-3.6
  // Uncut, the band from 2 to 3 m is one plane over both: it leans by about half the kink.
  const WallBandGrid uncut(1.0, {});
  bool straddles = false;
  for (const FramePatch& p : frame_wall_patches(map, walls, 0.0, Eigen::Vector3d::UnitZ(), SlamOptions(), uncut))
    if (uncut.from_m(p.band) == 2.0) {
      straddles = true;
      EXPECT_GT(std::abs(tilt_deg(p)), 0.5);
    }
  EXPECT_TRUE(straddles);
}

}  // namespace
}  // namespace tunnelmap
