// Pose refinement against the structure (StructureSlam): synthetic wall samples with known pose
// errors (exact recovery, degenerate views reported and left alone), and simulated arm sequences
// with sag fused with and without refinement.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/mesh_accuracy.h"
#include "core/io/dataset.h"
#include "core/io/refined_dataset.h"
#include "core/kinematics/robot_json.h"
#include "core/mapping/structure_slam.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"
#include "mesh/tsdf_mesher.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_fixture.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;

constexpr double kDeg = M_PI / 180.0;
constexpr double kW = 0.82, kH = 1.30;

// Camera looking along +X from (x, y, z), the simulator's neutral orientation.
Eigen::Isometry3d camera_at(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

Eigen::Isometry3d perturbation(double roll, double pitch, double yaw, const Eigen::Vector3d& t) {
  Eigen::Isometry3d P = Eigen::Isometry3d::Identity();
  P.linear() = (Eigen::AngleAxisd(yaw * kDeg, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(pitch * kDeg, Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(roll * kDeg, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  P.translation() = t;
  return P;
}

// What a frame at the true pose `T` measures of a box tunnel (world X along the axis, walls at
// y = +-W/2, z = 0 and H): samples on the walls in `walls` over x in [x0, x1], and a transverse
// plate at `plate_x` when set.
struct SyntheticFrame {
  TunnelMap map;
  FrameWalls walls;
};

SyntheticFrame observe(const Eigen::Isometry3d& T, double x0, double x1, const bool walls[4],
                       std::optional<double> plate_x = std::nullopt) {
  SyntheticFrame f;
  const Eigen::Isometry3d inv = T.inverse();
  f.map.detected = true;
  f.map.status = TunnelStatus::Ok;
  f.map.axis_dir = inv.linear() * Eigen::Vector3d::UnitX();
  f.map.up = inv.linear() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d inward[4] = {-Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY(),
                                     -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};
  for (int c = 0; c < 4; ++c) {
    f.map.walls[c].found = walls[c];
    f.map.walls[c].source = walls[c] ? DimensionSource::Measured : DimensionSource::Unseen;
    f.map.walls[c].normal = inv.linear() * inward[c];
  }
  int plane = 1;
  for (int c = 0; c < 4; ++c, ++plane) {
    if (!walls[c]) continue;
    for (double x = x0; x <= x1; x += 0.05)
      for (double s = 0.1; s < 0.9; s += 0.2) {
        Eigen::Vector3d p;
        if (c < 2) p = {x, c == 0 ? kW / 2 : -kW / 2, s * kH};
        else p = {x, (s - 0.5) * kW, c == 2 ? kH : 0.0};
        WallSample w;
        w.point = (inv * p).cast<float>();
        w.points = 64;
        w.plane = plane;
        w.wall = static_cast<std::uint8_t>(c);
        f.walls.samples.push_back(w);
      }
  }
  if (plate_x)
    for (double y = -0.3; y <= 0.3; y += 0.1)
      for (double z = 0.2; z <= 1.1; z += 0.15) {
        WallSample w;
        w.point = (inv * Eigen::Vector3d(*plate_x, y, z)).cast<float>();
        w.points = 64;
        w.plane = 9;
        w.wall = kTransverseSample;
        f.walls.samples.push_back(w);
      }
  return f;
}

double rotation_deg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() / kDeg;
}

bool has(const std::vector<std::string>& v, const char* s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// Forward kinematics of an arm whose sag reaches a degree: its uncertainty as the user sets it.
SlamOptions sagging_arm() {
  SlamOptions o;
  o.odometry_deg_per_sqrt_m = 2.0;
  o.odometry_m_per_sqrt_m = 0.05;
  return o;
}

// The batch estimate of StructureSlam over the frames, as `map` and `fuse` run it.
PoseRefinement refine(const std::vector<TunnelMap>& maps, const std::vector<FrameWalls>& walls,
                      const std::vector<Eigen::Isometry3d>& given, const std::vector<int>& groups,
                      SlamOptions options = SlamOptions()) {
  StructureSlam slam(options);
  for (std::size_t i = 0; i < maps.size(); ++i) slam.add_frame(maps[i], walls[i], given[i], groups[i]);
  return slam.finish();
}

TEST(PoseRefinement, RecoversAGroupsPoseErrorFromFourWallsAndAPlate) {
  const bool all[4] = {true, true, true, true};
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> given, truth;
  std::vector<int> groups;
  // Four poses, two frames each, all seeing the walls from x = 1 to 4 and a plate at 2 m; the
  // third pose is off by 1.2 deg and 25 mm (what arm sag does).
  const Eigen::Isometry3d error = perturbation(0.4, -1.0, 0.6, {0.012, -0.015, 0.018});
  for (int g = 0; g < 4; ++g)
    for (int k = 0; k < 2; ++k) {
      const Eigen::Isometry3d T = camera_at(0.2 * g + 0.01 * k, 0.05 * g - 0.08, 0.6 + 0.05 * k);
      SyntheticFrame f = observe(T, 1.0, 4.0, all, 2.0);
      maps.push_back(f.map);
      walls.push_back(f.walls);
      truth.push_back(T);
      given.push_back(g == 2 ? error * T : T);
      groups.push_back(g);
    }
  const PoseRefinement r = refine(maps, walls, given, groups, sagging_arm());
  ASSERT_TRUE(r.ran);
  ASSERT_EQ(r.groups.size(), 4u);
  for (std::size_t i = 0; i < given.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT(rotation_deg(r.poses[i], truth[i]), 0.02);
    EXPECT_LT((r.poses[i].translation() - truth[i].translation()).norm(), 0.0005);
  }
  EXPECT_NEAR(r.groups[2].rotation_deg, Eigen::AngleAxisd(error.linear()).angle() / kDeg, 0.02);
  EXPECT_GT(r.groups[2].translation_mm, 10.0);
  for (const PoseCorrection& c : r.groups) {
    EXPECT_EQ(c.constrained.size(), 6u) << c.group;
    EXPECT_TRUE(c.degenerate.empty()) << c.group;
  }
}

TEST(PoseRefinement, AFrameTooNearAPlateToSeeACrossSectionStillPlacesItselfByThePlate) {
  // Four stops see the walls and a plate at 3 m; the fifth, 0.9 m before the plate, sees the
  // plate alone and finds no cross-section (the walls beside it too short), and its odometry
  // puts it 30 mm short along the girder. The plate, which every stop measured, says where it is.
  const bool all[4] = {true, true, true, true}, none[4] = {false, false, false, false};
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> given, truth;
  std::vector<int> groups;
  for (int g = 0; g < 5; ++g)
    for (int k = 0; k < 2; ++k) {
      const double x = g < 4 ? 0.5 * g : 2.1;
      const Eigen::Isometry3d T = camera_at(x + 0.005 * k, 0.01, 0.6);
      SyntheticFrame f = g < 4 ? observe(T, x + 0.5, 2.9, all, 3.0) : observe(T, 0.0, 0.0, none, 3.0);
      if (g == 4) {
        f.map.detected = false;
        f.map.status = TunnelStatus::MissingWall;
      }
      maps.push_back(f.map);
      walls.push_back(f.walls);
      truth.push_back(T);
      given.push_back(g == 4 ? perturbation(0, 0, 0, {-0.030, 0.0, 0.0}) * T : T);
      groups.push_back(g);
    }
  const PoseRefinement r = refine(maps, walls, given, groups);
  ASSERT_TRUE(r.ran);
  for (std::size_t i = 0; i < given.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT(std::abs(r.poses[i].translation().x() - truth[i].translation().x()), 0.003);
  }
  ASSERT_EQ(r.groups.size(), 5u);
  EXPECT_NEAR(r.groups[4].translation_mm, 30.0, 3.0);
}

TEST(PoseRefinement, AFrameWithoutACrossSectionAddsAPlateOnlyOnceTheGirdersAxisIsKnown) {
  // Before any frame found a cross-section, the girder's axis is unknown and a plane facing the
  // camera may as well be a wall seen head-on: such a frame adds nothing. Later, frame by frame,
  // one 30 mm off along the girder is placed by the plate it shares with the stops before.
  const bool all[4] = {true, true, true, true}, none[4] = {false, false, false, false};
  const auto undetected = [&](const Eigen::Isometry3d& T) {
    SyntheticFrame f = observe(T, 0.0, 0.0, none, 3.0);
    f.map.detected = false;
    f.map.status = TunnelStatus::MissingWall;
    return f;
  };
  StructureSlam slam;
  const Eigen::Isometry3d start = camera_at(0.0, 0.01, 0.6);
  const SyntheticFrame first = undetected(start);
  slam.add_frame(first.map, first.walls, start, 0);
  EXPECT_EQ(slam.landmarks(), 0);
  for (int g = 1; g < 4; ++g) {
    const Eigen::Isometry3d T = camera_at(0.5 * g, 0.01, 0.6);
    const SyntheticFrame f = observe(T, 0.5 * g + 0.5, 2.9, all, 3.0);
    slam.add_frame(f.map, f.walls, T, g);
  }
  ASSERT_EQ(slam.plate_landmarks(), 1);
  const Eigen::Isometry3d truth = camera_at(2.1, 0.01, 0.6);
  const SyntheticFrame near = undetected(truth);
  const Eigen::Isometry3d placed =
      slam.add_frame(near.map, near.walls, perturbation(0, 0, 0, {-0.030, 0.0, 0.0}) * truth, 4);
  EXPECT_EQ(slam.plate_landmarks(), 1);
  EXPECT_LT(std::abs(placed.translation().x() - truth.translation().x()), 0.003);
}

// Side walls of two layers: edge bands (the outer surface) and a middle plate 8 mm proud of
// them, as a girder's walls are built. `edges`: whether the frame sees the edge bands too.
SyntheticFrame observe_layered(const Eigen::Isometry3d& T, double x0, double x1, bool edges) {
  const bool floor_and_roof[4] = {false, false, true, true};
  SyntheticFrame f = observe(T, x0, x1, floor_and_roof);
  const bool all[4] = {true, true, true, true};
  const SyntheticFrame box = observe(T, x0, x1, all);
  f.map.walls = box.map.walls;
  const Eigen::Isometry3d inv = T.inverse();
  constexpr double kProud = 0.008;
  for (int c = 0; c < 2; ++c)
    for (double x = x0; x <= x1; x += 0.05)
      for (double s = 0.05; s < 0.96; s += 0.1) {
        const bool middle = s > 0.3 && s < 0.7;
        if (!middle && !edges) continue;
        const double y = (c == 0 ? 1 : -1) * (kW / 2 - (middle ? kProud : 0.0));
        WallSample w;
        w.point = (inv * Eigen::Vector3d(x, y, s * kH)).cast<float>();
        w.points = 64;
        w.plane = middle ? 10 + c : 1 + c;
        w.wall = static_cast<std::uint8_t>(c);
        w.inset_m = middle ? static_cast<float>(kProud) : 0.0f;
        f.walls.samples.push_back(w);
      }
  return f;
}

TEST(PoseRefinement, AWallSeenOnlyOnItsMiddlePlateLandsOnThatLayer) {
  // The first poses see both layers of the side walls; the later ones, 6 mm off sideways (about
  // what the odometry drifts in a step), see only the middle plates. On one wall that view lies
  // 2 mm from the edge layer and 6 mm from the middle one, so alone it would take the edge
  // layer; the wall opposite, shifted the other way, tells which layer each sees.
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> given, truth;
  std::vector<int> groups;
  const Eigen::Isometry3d error = perturbation(0, 0, 0, {0.0, 0.006, 0.0});
  for (int g = 0; g < 5; ++g) {
    const Eigen::Isometry3d T = camera_at(0.25 * g, 0.02, 0.6);
    SyntheticFrame f = observe_layered(T, 0.5 + 0.25 * g, 3.0 + 0.25 * g, g < 2);
    maps.push_back(f.map);
    walls.push_back(f.walls);
    truth.push_back(T);
    given.push_back(g < 2 ? T : error * T);
    groups.push_back(g);
  }
  const PoseRefinement r = refine(maps, walls, given, groups);
  ASSERT_TRUE(r.ran);
  for (std::size_t i = 0; i < given.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_LT((r.poses[i].translation() - truth[i].translation()).norm(), 0.001);
  }
}

TEST(PoseRefinement, StationsAreArcLengthAlongACurvingWalk) {
  // A walk along a horizontal curve of 30 m radius (0.67 rad over 20 m): each frame sees the
  // girder straight ahead of it. Measured along the first frame's axis, the last station would
  // be R sin(0.67) = 18.5 m; along the walk it is 20 m.
  const bool all[4] = {true, true, true, true};
  const double radius = 30.0, step = 0.5;
  StructureSlam slam;
  std::vector<double> arc;
  for (int g = 0; g <= 40; ++g) {
    const double s = step * g, heading = s / radius;
    Eigen::Isometry3d T = camera_at(radius * std::sin(heading), radius * (1.0 - std::cos(heading)), 0.6);
    T.linear() = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
    const SyntheticFrame f = observe(camera_at(0.0, 0.0, 0.6), 0.5, 1.5, all);
    slam.add_frame(f.map, f.walls, T, g);
    arc.push_back(s);
  }
  const std::vector<double> stations = slam.group_stations_m();
  ASSERT_EQ(stations.size(), arc.size());
  for (std::size_t g = 0; g < arc.size(); ++g) EXPECT_NEAR(stations[g], arc[g], 0.005) << g;
}

TEST(PoseRefinement, TwoParallelWallsLeaveTheirDegenerateDirectionsAlone) {
  // Only the side walls: the pitch and the height (and, without a plate, the position along
  // the axis) are not constrained; they keep the given value and are reported.
  const bool sides[4] = {true, true, false, false};
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> given, truth;
  std::vector<int> groups;
  const Eigen::Isometry3d error = perturbation(0.0, 0.8, 0.7, {0.0, 0.02, 0.03});
  for (int g = 0; g < 3; ++g) {
    const Eigen::Isometry3d T = camera_at(0.2 * g, 0.0, 0.6);
    SyntheticFrame f = observe(T, 1.0, 4.0, sides);
    maps.push_back(f.map);
    walls.push_back(f.walls);
    truth.push_back(T);
    given.push_back(g == 1 ? error * T : T);
    groups.push_back(g);
  }
  const PoseRefinement r = refine(maps, walls, given, groups, sagging_arm());
  ASSERT_TRUE(r.ran);
  const PoseCorrection& c = r.groups[1];
  for (const char* d : {"pitch", "vertical", "axial"}) EXPECT_TRUE(has(c.degenerate, d)) << d;
  for (const char* d : {"roll", "yaw", "lateral"}) EXPECT_TRUE(has(c.constrained, d)) << d;
  // The constrained directions are corrected: yaw and the lateral offset are gone...
  const Eigen::Matrix3d R = r.poses[1].linear() * truth[1].linear().transpose();
  const Eigen::Vector3d x = R * Eigen::Vector3d::UnitX();
  // (What is left is the odometry's pull against the walls' millimetre patches.)
  EXPECT_NEAR(std::atan2(x.y(), x.x()) / kDeg, 0.0, 0.05);  // yaw
  EXPECT_NEAR(r.poses[1].translation().y(), truth[1].translation().y(), 0.0015);
  // ...and the degenerate ones are left as given: no confident wrong correction.
  EXPECT_NEAR(std::asin(-x.z()) / kDeg, std::asin(-(error.linear() * Eigen::Vector3d::UnitX()).z()) / kDeg, 0.02);
  EXPECT_NEAR(r.poses[1].translation().z(), given[1].translation().z(), 0.003);
}

TEST(PoseRefinement, APlateSeenByOneGroupOnlyDoesNotFixTheAxialPosition) {
  // The same plate seen twice by one group: nothing to compare it with, so the position along
  // the axis stays as given; the other directions come from the walls.
  const bool all[4] = {true, true, true, true};
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> given;
  std::vector<int> groups;
  for (int g = 0; g < 3; ++g)
    for (int k = 0; k < 2; ++k) {
      const Eigen::Isometry3d T = camera_at(0.2 * g, 0.0, 0.6);
      SyntheticFrame f = observe(T, 1.0, 4.0, all, g == 1 ? std::optional<double>(2.0) : std::nullopt);
      maps.push_back(f.map);
      walls.push_back(f.walls);
      given.push_back(g == 1 ? perturbation(0, 0, 0, {0.03, 0, 0}) * T : T);
      groups.push_back(g);
    }
  const PoseRefinement r = refine(maps, walls, given, groups);
  const PoseCorrection& c = r.groups[1];
  EXPECT_TRUE(has(c.degenerate, "axial"));
  // Along the axis every pose keeps its odometry: group 1 stays 30 mm ahead of the truth.
  for (std::size_t i = 0; i < given.size(); ++i)
    EXPECT_NEAR(r.poses[i].translation().x(), given[i].translation().x(), 1e-5) << i;
  EXPECT_NEAR(r.poses[2].translation().x() - 0.03, 0.2, 1e-5);
}

// What a structured-light camera does to a sample: its depth moves along its ray to the nearest
// disparity step (fx 570.3 px, baseline 75 mm, 1/8 pixel): a systematic error that grows with
// the square of the depth and does not average away.
void quantise_depths(FrameWalls& walls) {
  const double fx_b = 570.3 * 0.075, steps = 8.0;
  for (WallSample& w : walls.samples) {
    const double z = w.point.z();
    const double z_q = fx_b / (std::round(fx_b * steps / z) / steps);
    w.point *= static_cast<float>(z_q / z);
  }
}

// A walk of 40 poses, 0.25 m apart, each seeing the walls and the next plate; the camera's
// orientation wanders by a few tenths of a degree, as a climbing robot's does.
struct QuantisedWalk {
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> truth;
  std::vector<int> groups;
};

QuantisedWalk quantised_walk() {
  const bool all[4] = {true, true, true, true};
  QuantisedWalk w;
  for (int g = 0; g < 40; ++g) {
    const double x = 0.25 * g;
    const Eigen::Isometry3d T =
        camera_at(x, 0.03 * std::sin(0.7 * g), 0.6 + 0.02 * std::cos(1.3 * g)) *
        perturbation(0.3 * std::sin(1.1 * g), 0.25 * std::cos(0.9 * g), 0.2 * std::sin(0.5 * g), Eigen::Vector3d::Zero());
    SyntheticFrame f = observe(T, x + 0.6, x + 4.0, all, 2.0 * std::ceil((x + 0.5) / 2.0));
    quantise_depths(f.walls);
    w.maps.push_back(f.map);
    w.walls.push_back(f.walls);
    w.truth.push_back(T);
    w.groups.push_back(g);
  }
  return w;
}

double largest_correction_deg(const PoseRefinement& r) {
  double deg = 0.0;
  for (const PoseCorrection& c : r.groups) deg = std::max(deg, c.rotation_deg);
  return deg;
}

TEST(PoseRefinement, ExactPosesSeenThroughQuantisedDepthAreKept) {
  const QuantisedWalk w = quantised_walk();
  SlamOptions always;
  always.correction_sigmas = 0.0;
  // Fitted regardless of the evidence, the quantisation's systematic error moves exact poses...
  const PoseRefinement fitted = refine(w.maps, w.walls, w.truth, w.groups, always);
  EXPECT_GT(largest_correction_deg(fitted), 0.01);
  // ...which the evidence test declines: the structure agrees with them within its noise.
  const PoseRefinement r = refine(w.maps, w.walls, w.truth, w.groups);
  ASSERT_TRUE(r.ran);
  EXPECT_TRUE(r.given_poses_kept);
  EXPECT_FALSE(r.evidence.significant);
  EXPECT_EQ(r.evidence.dof, 6 * 39);
  EXPECT_LT(r.evidence.chi2_gain, r.evidence.threshold);
  for (std::size_t i = 0; i < w.truth.size(); ++i) EXPECT_TRUE(r.poses[i].isApprox(w.truth[i], 1e-12)) << i;
  for (const PoseCorrection& c : r.groups) EXPECT_LT(c.rotation_deg, 1e-9) << c.group;
}

TEST(PoseRefinement, FramesOfOneArmPoseShareTheirQuantisationError) {
  // Five frames from one arm pose see the walls on the same depth steps: together they say no
  // more about the pose than one of them, and the evidence must not grow fivefold.
  const QuantisedWalk w = quantised_walk();
  auto refine_repeated = [&](int repeats) {
    StructureSlam slam;
    for (std::size_t i = 0; i < w.maps.size(); ++i)
      for (int k = 0; k < repeats; ++k) slam.add_frame(w.maps[i], w.walls[i], w.truth[i], w.groups[i]);
    return slam.finish();
  };
  const PoseRefinement once = refine_repeated(1), fivefold = refine_repeated(5);
  std::printf("evidence: one frame per pose %.1f, five frames per pose %.1f (threshold %.1f)\n", once.evidence.chi2_gain,
              fivefold.evidence.chi2_gain, fivefold.evidence.threshold);
  EXPECT_EQ(fivefold.evidence.dof, once.evidence.dof);
  // Counted as independent they would multiply it by five. What is left is the robust loss: it
  // bends each patch's cost at two of its own sigmas, and five frames' patches each have
  // sqrt(5) times one frame's sigma, so a patch off by more than that weighs differently.
  EXPECT_NEAR(fivefold.evidence.chi2_gain, once.evidence.chi2_gain, 0.2 * once.evidence.chi2_gain + 0.5);
  EXPECT_TRUE(fivefold.given_poses_kept);
  for (std::size_t i = 0; i < fivefold.poses.size(); ++i) EXPECT_TRUE(fivefold.poses[i].isApprox(w.truth[i / 5], 1e-9)) << i;
}

// Each frame's pose as the window estimates it when the frame arrives (the robot on the move).
std::vector<Eigen::Isometry3d> localise_while_walking(const QuantisedWalk& w, const std::vector<Eigen::Isometry3d>& given,
                                                     SlamOptions options = SlamOptions()) {
  StructureSlam slam(options);
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t i = 0; i < w.maps.size(); ++i) poses.push_back(slam.add_frame(w.maps[i], w.walls[i], given[i], w.groups[i]));
  return poses;
}

double worst_rotation_deg(const std::vector<Eigen::Isometry3d>& a, const std::vector<Eigen::Isometry3d>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, rotation_deg(a[i], b[i]));
  return worst;
}

// A plate seen far away through the manhole of a near one, pixel by pixel as the camera does:
// depth noise growing with z^2 (2.5 mm at 1 m), pixels beyond the cloud's 5 m range dropped,
// and the rest averaged in 8 x 8 blocks. Near the range only the pixels that the noise brought
// nearer are left, and the plate comes out too near.
void add_far_plate(const Eigen::Isometry3d& T, double plate_x, std::mt19937& rng, FrameWalls& walls) {
  const Eigen::Isometry3d inv = T.inverse();
  std::normal_distribution<double> unit(0.0, 1.0);
  for (double y = -0.15; y <= 0.15; y += 0.05)
    for (double z = 0.35; z <= 0.85; z += 0.05) {
      const Eigen::Vector3d p = inv * Eigen::Vector3d(plate_x, y, z);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int kept = 0;
      for (int k = 0; k < 64; ++k) {
        const double depth = p.z() + unit(rng) * 0.0025 * p.z() * p.z();
        if (depth > 5.0) continue;
        sum += p * (depth / p.z());
        ++kept;
      }
      if (kept == 0) continue;
      WallSample w;
      w.point = (sum / kept).cast<float>();
      w.points = kept;
      w.plane = 10;
      w.wall = kTransverseSample;
      walls.samples.push_back(w);
    }
}

TEST(PoseRefinement, APlateNearTheCloudsRangeDoesNotShrinkTheMap) {
  // Exact poses walking 20 m through compartments 4 m long, a stop every 10 cm, each seeing
  // the plate ahead and, within 1 m of it, the next plate through its manhole (4.1 to 5 m
  // away). Corrected whatever the evidence, the poses must stay where they are: a far plate
  // cut by the range pulls every crossing short.
  const bool all[4] = {true, true, true, true};
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> truth;
  std::vector<int> groups;
  std::mt19937 rng(7);
  for (int g = 0; g < 200; ++g) {
    const double x = 0.1 * g;
    const Eigen::Isometry3d T = camera_at(x, 0.02 * std::sin(0.7 * g), 0.6);
    const double near_plate = 4.0 * std::floor(x / 4.0 + 1e-9) + 4.0;
    SyntheticFrame f = observe(T, x + 0.6, std::min(x + 4.0, near_plate - 0.05), all, near_plate);
    if (near_plate - x < 1.0 + 1e-9) add_far_plate(T, near_plate + 4.0, rng, f.walls);
    maps.push_back(f.map);
    walls.push_back(f.walls);
    truth.push_back(T);
    groups.push_back(g);
  }
  SlamOptions always;
  always.correction_sigmas = 0.0;
  const PoseRefinement r = refine(maps, walls, truth, groups, always);
  double worst_mm = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    worst_mm = std::max(worst_mm, 1000.0 * std::abs(r.poses[i].translation().x() - truth[i].translation().x()));
  std::printf("along the girder, worst correction of exact poses: %.2f mm\n", worst_mm);
  EXPECT_LT(worst_mm, 1.5);
}

// A box girder's walls as a frame at `T` sees them over x in [x0, x1]: on each wall of
// `walls`, edge bands along both corners (the outer surface) and a middle plate 8 mm inside.
SyntheticFrame observe_zoned(const Eigen::Isometry3d& T, double x0, double x1, const bool walls[4],
                             std::optional<double> plate_x = std::nullopt) {
  SyntheticFrame f = observe(T, x0, x1, walls, plate_x);
  std::vector<WallSample>& samples = f.walls.samples;
  samples.erase(std::remove_if(samples.begin(), samples.end(), [](const WallSample& w) { return w.wall != kTransverseSample; }),
                samples.end());
  const Eigen::Isometry3d inv = T.inverse();
  constexpr double kPlate = 0.008;
  for (int c = 0; c < 4; ++c) {
    if (!walls[c]) continue;
    for (double x = x0; x <= x1; x += 0.05)
      for (double s = 0.05; s < 1.0; s += 0.1) {
        const bool middle = s > 0.2 && s < 0.8;
        const double in = middle ? kPlate : 0.0;
        Eigen::Vector3d p;
        if (c < 2) p = {x, c == 0 ? kW / 2 - in : -kW / 2 + in, s * kH};
        else p = {x, (s - 0.5) * kW, c == 2 ? kH - in : in};
        WallSample w;
        w.point = (inv * p).cast<float>();
        w.points = 64;
        w.plane = 1 + 2 * c + (middle ? 1 : 0);
        w.wall = static_cast<std::uint8_t>(c);
        w.inset_m = static_cast<float>(in);
        f.walls.samples.push_back(w);
      }
  }
  return f;
}

// A walk of 33 poses 0.25 m apart through a diaphragm at x = 4 m: near the plate the camera
// sees only the side walls; past it, the floor and roof of a new compartment that no earlier
// frame saw. Beyond the plate the floor and roof lie `section_step_m` lower.
struct PlateWalk {
  static constexpr double kPlateX = 4.0;
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> truth;
  std::vector<int> groups;
};

PlateWalk plate_walk(double section_step_m = 0.0) {
  const bool all[4] = {true, true, true, true}, sides[4] = {true, true, false, false};
  constexpr double kPlateX = PlateWalk::kPlateX;
  PlateWalk w;
  for (int g = 0; g < 33; ++g) {
    const double x = 0.25 * g;
    const Eigen::Isometry3d T = camera_at(x, 0.02 * std::sin(0.7 * g), 0.6 + 0.03 * std::cos(0.9 * g));
    const bool blind = x > kPlateX - 1.0 && x < kPlateX + 0.3;
    const double x1 = x < kPlateX ? kPlateX - 0.05 : x + 4.0;
    const std::optional<double> plate = x < kPlateX ? std::optional<double>(kPlateX) : std::nullopt;
    SyntheticFrame f = observe_zoned(T, std::max(x + 0.6, x < kPlateX ? 0.0 : kPlateX + 0.05), x1, blind ? sides : all, plate);
    for (WallSample& s : f.walls.samples)
      if ((s.wall == 2 || s.wall == 3) && (T * s.point.cast<double>()).x() > kPlateX)
        s.point += (T.inverse().linear() * Eigen::Vector3d(0.0, 0.0, -section_step_m)).cast<float>();
    w.maps.push_back(f.map);
    w.walls.push_back(f.walls);
    w.truth.push_back(T);
    w.groups.push_back(g);
  }
  return w;
}

// The odometry slips 20 mm up over the blind stretch at the plate of plate_walk().
std::vector<Eigen::Isometry3d> slipped_over_plate(const std::vector<Eigen::Isometry3d>& truth) {
  constexpr double kSlipM = 0.02;
  std::vector<Eigen::Isometry3d> given;
  for (const Eigen::Isometry3d& T : truth) {
    Eigen::Isometry3d G = T;
    G.translation().z() += kSlipM * std::clamp((T.translation().x() - (PlateWalk::kPlateX - 1.0)) / 1.3, 0.0, 1.0);
    given.push_back(G);
  }
  return given;
}

struct TiedAndFreeMm {
  double tied_mm, free_mm;
};

// The worst height error of the poses of `w`, given with the odometry's slip over the plate
// and corrected whatever the evidence (one slip over a short walk is within its noise), with
// the walls tied across the plate (2 mm) and left free.
TiedAndFreeMm height_errors_after_a_slip(const PlateWalk& w) {
  const std::vector<Eigen::Isometry3d> given = slipped_over_plate(w.truth);
  auto worst_height_error_mm = [&](const PoseRefinement& r) {
    double worst = 0.0;
    for (std::size_t i = 0; i < w.truth.size(); ++i)
      worst = std::max(worst, 1000.0 * std::abs(r.poses[i].translation().z() - w.truth[i].translation().z()));
    return worst;
  };
  SlamOptions tied_walls, free_walls;
  tied_walls.correction_sigmas = free_walls.correction_sigmas = 0.0;
  tied_walls.wall_continuity_m = 0.002;
  free_walls.wall_continuity_m = 0.0;
  return {worst_height_error_mm(refine(w.maps, w.walls, given, w.groups, tied_walls)),
          worst_height_error_mm(refine(w.maps, w.walls, given, w.groups, free_walls))};
}

TEST(PoseRefinement, TheFloorBeyondAPlateContinuesTheFloorBeforeIt) {
  // The odometry slips 20 mm up over the blind stretch at the plate. The walls run on through
  // the plate, so the map beyond it is brought back down to the floor before it; left free,
  // each compartment keeps wherever the odometry put it.
  const TiedAndFreeMm r = height_errors_after_a_slip(plate_walk());
  std::printf("height error past the plate: walls tied %.2f mm, walls free %.2f mm\n", r.tied_mm, r.free_mm);
  EXPECT_GT(r.free_mm, 15.0);
  EXPECT_LT(r.tied_mm, 5.0);
}

// The walk of plate_walk(), with `wall` moved by `shift` (world) past the plate: a new section
// starts there.
PlateWalk stepped_past_plate(int wall, const Eigen::Vector3d& shift) {
  PlateWalk w = plate_walk();
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    const Eigen::Isometry3d& T = w.truth[i];
    for (WallSample& s : w.walls[i].samples)
      if (s.wall == wall && (T * s.point.cast<double>()).x() > PlateWalk::kPlateX)
        s.point += (T.inverse().linear() * shift).cast<float>();
  }
  return w;
}

// Past the plate of plate_walk() the roof rises by `rise_m` (a taller section) while the floor
// runs on; the frames 1-2 m before the plate see that floor beyond it through the manhole,
// from 0.3 to 1.5 m past the plate.
PlateWalk taller_past_plate(double rise_m) {
  constexpr double kPlateX = PlateWalk::kPlateX;
  const bool floor_only[4] = {false, false, false, true};
  PlateWalk w = stepped_past_plate(2, Eigen::Vector3d(0.0, 0.0, rise_m));
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    const Eigen::Isometry3d& T = w.truth[i];
    const double x = T.translation().x();
    if (x < kPlateX - 1.0 && x > kPlateX - 2.0)
      for (WallSample s : observe_zoned(T, kPlateX + 0.3, kPlateX + 1.5, floor_only).walls.samples) {
        s.plane += 20;  // a plane of its own, seen through the opening
        w.walls[i].samples.push_back(s);
      }
  }
  return w;
}

TEST(PoseRefinement, ARoofThatRisesPastAPlateIsNotTiedToTheRoofBeforeIt) {
  // The odometry slips 20 mm up over the blind stretch at the plate, and past the plate the
  // roof rises by 28 mm. The frames that see the floor beyond the plate through the manhole
  // place the compartment beyond; the roof's tie across the plate, held, would pull it to
  // meet the roof before the plate (measured: 38.8 mm off). The floor's and the roof's ties
  // disagree by the change of height the frames measured either side, so neither is applied,
  // and the map beyond the plate ends where it does with the walls left free (3.5 mm: the
  // blind frames at the plate keep part of the slip).
  const TiedAndFreeMm r = height_errors_after_a_slip(taller_past_plate(0.028));
  std::printf("height error past a rising roof: walls tied %.2f mm, walls free %.2f mm\n", r.tied_mm, r.free_mm);
  EXPECT_LT(r.free_mm, 5.0);
  EXPECT_LT(r.tied_mm, r.free_mm + 0.2);
}

// The odometry turns by `deg` about world `axis` over the blind stretch at the plate at
// `plate_x` (of plate_walk() or plates_walk()), its position staying right.
std::vector<Eigen::Isometry3d> turned_over_plate(const std::vector<Eigen::Isometry3d>& truth, const Eigen::Vector3d& axis,
                                                 double deg, double plate_x = PlateWalk::kPlateX) {
  std::vector<Eigen::Isometry3d> given;
  for (const Eigen::Isometry3d& T : truth) {
    const double share = std::clamp((T.translation().x() - (plate_x - 1.0)) / 1.3, 0.0, 1.0);
    Eigen::Isometry3d G = T;
    G.linear() = Eigen::AngleAxisd(share * deg * kDeg, axis).toRotationMatrix() * T.linear();
    given.push_back(G);
  }
  return given;
}

// The worst rotation error of the frames past `plate_x`, corrected whatever the evidence.
double worst_rotation_past_deg(const PlateWalk& w, const std::vector<Eigen::Isometry3d>& given, SlamOptions options,
                               double plate_x) {
  options.correction_sigmas = 0.0;
  const PoseRefinement r = refine(w.maps, w.walls, given, w.groups, options);
  double worst = 0.0;
  for (std::size_t i = 0; i < w.truth.size(); ++i)
    if (w.truth[i].translation().x() > plate_x) worst = std::max(worst, rotation_deg(r.poses[i], w.truth[i]));
  return worst;
}

struct TiedAndFree {
  double tied_deg, free_deg;
};

TEST(PoseRefinement, TheCompartmentBeyondAPlateDoesNotRollAwayFromTheOneBeforeIt) {
  // No frame sees both sides of the plate: past it, only the odometry says how the new
  // compartment is rolled, and it rolls by 1 degree over the climb. The walls run on through
  // the plate without rolling, so the map beyond it is rolled back (measured: 0.025 degrees).
  const PlateWalk w = plate_walk();
  const std::vector<Eigen::Isometry3d> given = turned_over_plate(w.truth, Eigen::Vector3d::UnitX(), 1.0);
  SlamOptions tied, free;
  tied.wall_turn_rad = 0.05 * kDeg;
  free.wall_turn_rad = 0.0;
  const TiedAndFree r{worst_rotation_past_deg(w, given, tied, PlateWalk::kPlateX),
                      worst_rotation_past_deg(w, given, free, PlateWalk::kPlateX)};
  std::printf("roll past the plate: walls tied %.3f deg, free %.3f deg\n", r.tied_deg, r.free_deg);
  EXPECT_GT(r.free_deg, 0.5);
  EXPECT_LT(r.tied_deg, 0.05);
}

TEST(PoseRefinement, AWiderSectionPastAPlateStillDoesNotRoll) {
  // The same roll over the climb, and past the plate the left wall lies 30 mm further out. The
  // side walls' distances are not held across that plate: held, they pulled the map beyond
  // the plate 6.6 mm sideways. Their directions still are, and the map beyond is rolled back
  // as before.
  const PlateWalk w = stepped_past_plate(0, Eigen::Vector3d(0.0, 0.03, 0.0));
  const std::vector<Eigen::Isometry3d> given = turned_over_plate(w.truth, Eigen::Vector3d::UnitX(), 1.0);
  SlamOptions tied, free_roll;
  tied.correction_sigmas = free_roll.correction_sigmas = 0.0;
  tied.wall_turn_rad = 0.05 * kDeg;
  free_roll.wall_turn_rad = 0.0;
  const PoseRefinement r = refine(w.maps, w.walls, given, w.groups, tied);
  double worst_deg = 0.0, worst_sideways_mm = 0.0;
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    if (w.truth[i].translation().x() <= PlateWalk::kPlateX) continue;
    worst_deg = std::max(worst_deg, rotation_deg(r.poses[i], w.truth[i]));
    worst_sideways_mm = std::max(worst_sideways_mm, 1000.0 * std::abs(r.poses[i].translation().y() - w.truth[i].translation().y()));
  }
  const double free_deg = worst_rotation_past_deg(w, given, free_roll, PlateWalk::kPlateX);
  std::printf("past a wider section: roll %.3f deg (free %.3f), sideways %.2f mm\n", worst_deg, free_deg,
              worst_sideways_mm);
  EXPECT_GT(free_deg, 0.5);
  EXPECT_LT(worst_deg, 0.05);
  EXPECT_LT(worst_sideways_mm, 3.0);
}

// A walk of 121 poses 0.25 m apart through diaphragms every 4 m from x = 4 to 28 m: each frame
// sees the walls ahead up to the next plate, and that plate; near a plate only the side walls.
PlateWalk plates_walk() {
  const bool all[4] = {true, true, true, true}, sides[4] = {true, true, false, false};
  constexpr double kSpacing = 4.0, kLast = 28.0;
  PlateWalk w;
  for (int g = 0; g < 121; ++g) {
    const double x = 0.25 * g;
    const Eigen::Isometry3d T = camera_at(x, 0.02 * std::sin(0.7 * g), 0.6 + 0.03 * std::cos(0.9 * g));
    const double ahead = kSpacing * std::floor(x / kSpacing + 1.0), behind = ahead - kSpacing;
    const std::optional<double> plate = ahead <= kLast ? std::optional<double>(ahead) : std::nullopt;
    const bool blind = (plate && ahead - x < 1.0) || (behind > 0.0 && x - behind < 0.3);
    const SyntheticFrame f = observe_zoned(T, x + 0.6, plate ? ahead - 0.05 : x + 4.0, blind ? sides : all, plate);
    w.maps.push_back(f.map);
    w.walls.push_back(f.walls);
    w.truth.push_back(T);
    w.groups.push_back(g);
  }
  return w;
}

// Dead reckoning turned by `deg` about world Z over the blind stretch at the plate at
// `plate_x`: each frame past it is swung about the plate.
std::vector<Eigen::Isometry3d> swung_over_plate(const std::vector<Eigen::Isometry3d>& poses, double deg, double plate_x) {
  const std::vector<Eigen::Isometry3d> turned = turned_over_plate(poses, Eigen::Vector3d::UnitZ(), deg, plate_x);
  std::vector<Eigen::Isometry3d> given = turned;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const Eigen::Matrix3d turn = turned[i].linear() * poses[i].linear().transpose();
    const Eigen::Vector3d pivot(plate_x, 0.0, poses[i].translation().z());
    given[i].translation() = pivot + turn * (poses[i].translation() - pivot);
  }
  return given;
}

TEST(PoseRefinement, ACompartmentDoesNotTurnAwayFromItsNeighbours) {
  // The heading, at the plates of a straight girder. A curving girder turns, and a chorded one
  // kinks at its plates, so no wall is tied to the next across a plate. But a girder's turn
  // changes evenly: each compartment's direction lies on the quadratic through its
  // neighbours'. The odometry turns 0.6 degrees over the climb at 12 m and back at 16 m,
  // carrying the positions with it (dead reckoning): the compartment between is turned back
  // as far as the ties can tell a jog from a quadratic: the best quadratic through the six
  // compartments keeps 0.37 of a one-compartment jog, 0.22 degrees (measured: 0.215). Left
  // free it keeps most of the turn (0.41 degrees).
  const PlateWalk w = plates_walk();
  const std::vector<Eigen::Isometry3d> given = swung_over_plate(swung_over_plate(w.truth, 0.6, 12.0), -0.6, 16.0);
  SlamOptions tied, free;
  tied.compartment_turn_rad = 0.01 * kDeg;
  free.compartment_turn_rad = 0.0;
  const TiedAndFree r{worst_rotation_past_deg(w, given, tied, 0.0), worst_rotation_past_deg(w, given, free, 0.0)};
  std::printf("heading: compartments tied %.3f deg, free %.3f deg\n", r.tied_deg, r.free_deg);
  EXPECT_GT(r.free_deg, 0.3);
  EXPECT_LT(r.tied_deg, 0.24);
}

TEST(PoseRefinement, TheWallTiesShapeTheFinalOptimisationNotTheWalk) {
  // While the walk runs, each window corrects what the measurements alone demand: a window
  // shaped by the ties would start the final evidence test away from the measurements' own
  // optimum, and exact poses could then be corrected. The poses while walking are therefore
  // the same with and without the ties; the final optimisation applies them.
  const PlateWalk w = plate_walk();
  const std::vector<Eigen::Isometry3d> given = slipped_over_plate(w.truth);
  SlamOptions tied_walls, free_walls;
  tied_walls.correction_sigmas = free_walls.correction_sigmas = 0.0;
  tied_walls.wall_continuity_m = 0.002;
  free_walls.wall_continuity_m = 0.0;
  StructureSlam tied(tied_walls), free(free_walls);
  double worst_difference_mm = 0.0, worst_tied_mm = 0.0;
  for (std::size_t i = 0; i < w.maps.size(); ++i) {
    const Eigen::Isometry3d a = tied.add_frame(w.maps[i], w.walls[i], given[i], w.groups[i]);
    const Eigen::Isometry3d b = free.add_frame(w.maps[i], w.walls[i], given[i], w.groups[i]);
    worst_difference_mm = std::max(worst_difference_mm, 1000.0 * (a.translation() - b.translation()).norm());
  }
  const PoseRefinement final_tied = tied.finish();
  for (std::size_t i = 0; i < w.truth.size(); ++i)
    worst_tied_mm = std::max(worst_tied_mm, 1000.0 * std::abs(final_tied.poses[i].translation().z() - w.truth[i].translation().z()));
  std::printf("while walking: tied and free differ by %.4f mm; final, tied: %.2f mm\n", worst_difference_mm, worst_tied_mm);
  EXPECT_LT(worst_difference_mm, 1e-6);
  EXPECT_LT(worst_tied_mm, 5.0);
}

TEST(PoseRefinement, ASectionThatStepsAtAPlateLeavesExactPosesExact) {
  // Exact poses, and beyond the diaphragm the floor and roof lie 6 mm lower (the girder settled
  // there, or its plates are thicker): the walls' continuity across the plate, however tight,
  // disagrees with what was measured. The correction is the measurements' to demand; a tie
  // only shapes one.
  const PlateWalk w = plate_walk(0.006);
  SlamOptions tight;
  tight.wall_continuity_m = 0.0001;
  const PoseRefinement r = refine(w.maps, w.walls, w.truth, w.groups, tight);
  ASSERT_TRUE(r.ran);
  // The measurements agree with the exact poses: no gain at all (with the ties counted, 80).
  EXPECT_LT(r.evidence.chi2_gain, 1.0);
  EXPECT_TRUE(r.given_poses_kept);
  for (std::size_t i = 0; i < w.truth.size(); ++i) EXPECT_TRUE(r.poses[i].isApprox(w.truth[i], 1e-9)) << i;
}

TEST(PoseRefinement, ExactPosesStayExactWhileTheWalkRuns) {
  const QuantisedWalk w = quantised_walk();
  SlamOptions always;
  always.correction_sigmas = 0.0;
  // Each window fitted regardless of the evidence follows the quantisation's systematic error...
  EXPECT_GT(worst_rotation_deg(localise_while_walking(w, w.truth, always), w.truth), 0.01);
  // ...which the window's own evidence test declines, frame after frame.
  const std::vector<Eigen::Isometry3d> poses = localise_while_walking(w, w.truth);
  for (std::size_t i = 0; i < w.truth.size(); ++i) EXPECT_TRUE(poses[i].isApprox(w.truth[i], 1e-9)) << i;
}

TEST(PoseRefinement, DriftedPosesAreCorrectedWhileTheWalkRuns) {
  // Odometry whose heading drifts by 0.03 degrees per step: 1.2 degrees by the last pose.
  const QuantisedWalk w = quantised_walk();
  std::vector<Eigen::Isometry3d> given;
  for (std::size_t g = 0; g < w.truth.size(); ++g) {
    Eigen::Isometry3d T = w.truth[g];
    T.linear() = Eigen::AngleAxisd(0.03 * kDeg * g, Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
    given.push_back(T);
  }
  const double given_deg = worst_rotation_deg(given, w.truth);
  const double localised_deg = worst_rotation_deg(localise_while_walking(w, given), w.truth);
  std::printf("heading drift: given %.3f deg, localised while walking %.3f deg (worst)\n", given_deg, localised_deg);
  EXPECT_GT(given_deg, 1.1);
  EXPECT_LT(localised_deg, 0.5 * given_deg);
}

TEST(PoseRefinement, DriftedPosesSeenThroughQuantisedDepthAreCorrected) {
  // The same walk with odometry whose heading drifts by 0.03 degrees and whose position slips
  // 1.5 mm sideways per step: 1.2 degrees and 59 mm by the last pose.
  const QuantisedWalk w = quantised_walk();
  std::vector<Eigen::Isometry3d> given;
  for (std::size_t g = 0; g < w.truth.size(); ++g) {
    Eigen::Isometry3d T = w.truth[g];
    T.linear() = Eigen::AngleAxisd(0.03 * kDeg * g, Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
    T.translation().y() += 0.0015 * g;
    given.push_back(T);
  }
  const PoseRefinement r = refine(w.maps, w.walls, given, w.groups);
  ASSERT_TRUE(r.ran);
  EXPECT_TRUE(r.evidence.significant);
  EXPECT_FALSE(r.given_poses_kept);
  double worst_deg = 0.0, worst_m = 0.0;
  for (std::size_t i = 0; i < given.size(); ++i) {
    worst_deg = std::max(worst_deg, rotation_deg(r.poses[i], w.truth[i]));
    worst_m = std::max(worst_m, std::abs(r.poses[i].translation().y() - w.truth[i].translation().y()));
  }
  // Walls cut into 1 m bands let a slow bend through (0.31 degrees and 24 mm are left here), so
  // the bound is the drift's reduction, not its removal.
  EXPECT_LT(worst_deg, 0.4);
  EXPECT_LT(worst_m, 0.03);
}

TEST(PoseRefinement, AFrameWhoseOdometryHeadingIsFarOffStillLandsOnTheMap) {
  // Steps of 0.5 m whose heading drifts by 0.5 degrees each, the position drifting in the
  // world as the simulator draws it: by the 20th step the odometry's heading is 10 degrees
  // off the map's. A step composed in the drifted camera's frame would start each new frame
  // 9 cm sideways, past where its walls land on the map's, and the walk would go on with
  // walls of its own and the odometry's heading.
  const bool all[4] = {true, true, true, true};
  QuantisedWalk w;
  std::vector<Eigen::Isometry3d> given;
  for (int g = 0; g < 30; ++g) {
    const double x = 0.5 * g;
    const Eigen::Isometry3d T = camera_at(x, 0.02 * std::sin(0.7 * g), 0.6);
    const SyntheticFrame f = observe_zoned(T, x + 0.6, x + 4.0, all);
    w.maps.push_back(f.map);
    w.walls.push_back(f.walls);
    w.truth.push_back(T);
    w.groups.push_back(g);
    Eigen::Isometry3d G = T;
    G.linear() = Eigen::AngleAxisd(0.5 * kDeg * g, Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
    given.push_back(G);
  }
  StructureSlam drifted, exact;
  double localised_deg = 0.0;
  for (std::size_t i = 0; i < w.maps.size(); ++i) {
    const Eigen::Isometry3d pose = drifted.add_frame(w.maps[i], w.walls[i], given[i], w.groups[i]);
    exact.add_frame(w.maps[i], w.walls[i], w.truth[i], w.groups[i]);
    localised_deg = std::max(localised_deg, rotation_deg(pose, w.truth[i]));
  }
  const double given_deg = worst_rotation_deg(given, w.truth);
  std::printf("heading drift: given %.2f deg, localised while walking %.3f deg (worst); landmarks %d, exact poses %d\n",
              given_deg, localised_deg, drifted.landmarks(), exact.landmarks());
  EXPECT_GT(given_deg, 14.0);
  // Every frame landed on the walls the exact walk mapped (composed in the camera's frame: 316
  // landmarks for 152, and 6 degrees off while walking). One band may get a layer of its own
  // where the windows' three iterations left it a few millimetres from the rest, as the
  // solver's path decides: 153 with the planes anchored where they were seen, 152 before.
  EXPECT_LE(drifted.landmarks(), exact.landmarks() + 1);
  EXPECT_GE(drifted.landmarks(), exact.landmarks());
  EXPECT_LT(localised_deg, 1.0);
}

// --- Simulated arm sequences with sag, fused ----------------------------------------------

// Arm sequences at 0, 1 and 2 deg/m of sag, simulated once per build and shared by every test
// here: tests read `shared` and write into their own folder.
class SagFusion : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string what = "lab, 12 frames, seed 7, inchworm7, sag 0 1 2 deg/m\n" + testing::test_binary_stamp();
    shared = testing::shared_fixture("SagFusion", what, [](const std::filesystem::path& dir) {
      for (double sag : {0.0, 1.0, 2.0}) {
        SimConfig c = SimConfig::from_preset("lab");
        c.frames = 12;
        c.seed = 7;
        c.arm_preset = "inchworm7";
        c.arm_sag_deg_per_m = sag;
        write_sim_dataset((dir / ("sag" + std::to_string(int(sag)))).string(), c);
      }
      return std::string();
    });
    ASSERT_TRUE(shared.ok()) << shared.error;
  }
  static testing::SharedFixture shared;
  IoTempDir tmp;  // this test's own outputs

  struct Fused {
    double aligned_within = 0.0;   // mesh vertices within 10 mm after one rigid alignment
    double worst_deg = 0.0, worst_mm = 0.0;  // refined poses vs the truth (same alignment)
    FusionResult result;
  };

  static Fused fuse(int sag, bool refine) {
    const Dataset ds = read_dataset(shared.file("sag" + std::to_string(sag)));
    Parameters p;
    p.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/lab.json");
    p.set("fusion.voxel_mm", 10.0);
    // The arm sags by up to 2 deg per metre of reach: the forward kinematics' uncertainty.
    p.set("slam.odometry_deg_per_sqrt_m", 2.0);
    FuseSettings s;
    s.refine_poses = refine;
    Fused f;
    f.result = fuse_dataset(ds, p, s);
    const TriangleMesh mesh = extract_mesh(*f.result.volume, 2);
    const auto truth = ground_truth_planes(ds.ground_truth);
    const Eigen::Isometry3d A = align_mesh_to_planes(mesh, truth);
    f.aligned_within = mesh_accuracy(transformed(mesh, A), truth).fraction_within;
    // Poses against the truth up to one rigid motion of the whole sequence (where it sits in
    // the world is not observable along a straight tunnel): the mean rotation, then the
    // translation of the camera centres' mean.
    const std::size_t n = ds.frames.size();
    Eigen::Matrix3Xd est_c(3, n), true_c(3, n);
    std::vector<Eigen::Isometry3d> truth_poses;
    for (std::size_t i = 0; i < n; ++i) {
      truth_poses.push_back(isometry_from_json(ds.frames[i].raw["pose_true"], "test", "pose_true"));
      est_c.col(static_cast<Eigen::Index>(i)) = f.result.frames[i].camera_to_world.translation();
      true_c.col(static_cast<Eigen::Index>(i)) = truth_poses.back().translation();
    }
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < n; ++i)
      sum += truth_poses[i].linear() * f.result.frames[i].camera_to_world.linear().transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Isometry3d G = Eigen::Isometry3d::Identity();
    G.linear() = svd.matrixU() * svd.matrixV().transpose();
    G.translation() = true_c.rowwise().mean() - G.linear() * est_c.rowwise().mean();
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Isometry3d est = G * f.result.frames[i].camera_to_world;
      f.worst_deg = std::max(f.worst_deg, rotation_deg(est, truth_poses[i]));
      f.worst_mm = std::max(f.worst_mm, (est.translation() - truth_poses[i].translation()).norm() * 1000.0);
    }
    return f;
  }
};
testing::SharedFixture SagFusion::shared;

TEST_F(SagFusion, RefinementKeepsTheMeshWithin10mmAt1And2DegPerMetre) {
  for (int sag : {1, 2}) {
    SCOPED_TRACE(sag);
    const Fused given = fuse(sag, false);
    const Fused refined = fuse(sag, true);
    std::printf("sag %d deg/m: %.2f %% within 10 mm after alignment (not refined %.2f %%); "
                "poses within %.3f deg, %.1f mm (not refined %.3f deg, %.1f mm)\n", sag,
                100 * refined.aligned_within, 100 * given.aligned_within, refined.worst_deg,
                refined.worst_mm, given.worst_deg, given.worst_mm);
    EXPECT_GE(refined.aligned_within, 0.99);
    EXPECT_GE(refined.aligned_within, given.aligned_within - 0.001);
    EXPECT_LT(refined.worst_deg, 0.2);
    EXPECT_LT(refined.worst_mm, 5.0);
    EXPECT_LT(refined.worst_deg, given.worst_deg);
    ASSERT_TRUE(refined.result.refinement.ran);
    // Four walls in view fix the rotation and the cross-section; the end wall lies beyond the
    // depth where a face is trusted for the position along the axis.
    for (const PoseCorrection& c : refined.result.refinement.groups)
      for (const char* d : {"roll", "pitch", "yaw", "lateral", "vertical"})
        EXPECT_TRUE(has(c.constrained, d)) << c.group << " " << d;
  }
}

TEST_F(SagFusion, WithoutSagRefinementChangesNothingThatMatters) {
  const Fused given = fuse(0, false);
  const Fused refined = fuse(0, true);
  std::printf("no sag: %.2f %% within 10 mm after alignment (not refined %.2f %%); poses within "
              "%.3f deg, %.1f mm\n", 100 * refined.aligned_within, 100 * given.aligned_within,
              refined.worst_deg, refined.worst_mm);
  EXPECT_GE(refined.aligned_within, given.aligned_within - 0.001);
  // Exact poses stay within the accuracy the refinement promises (measured: 0.16 deg, 4.6 mm
  // for the rolled pose whose walls are seen at the most grazing angles).
  for (const PoseCorrection& c : refined.result.refinement.groups) {
    EXPECT_LT(c.rotation_deg, 0.2) << c.group;
    EXPECT_LT(c.translation_mm, 5.0) << c.group;
  }
  EXPECT_LT(refined.worst_deg, 0.2);
  EXPECT_LT(refined.worst_mm, 5.0);
}

TEST_F(SagFusion, TheRefinedDatasetIsReadLikeAnyOther) {
  const Fused refined = fuse(2, true);
  const Dataset ds = read_dataset(shared.file("sag2"));
  std::vector<Eigen::Isometry3d> poses;
  for (const FusedFrame& f : refined.result.frames) poses.push_back(f.camera_to_world);
  const std::string out = tmp.file("refined2");
  write_dataset_with_poses(ds, poses, out);
  const Dataset back = read_dataset(out);
  ASSERT_EQ(back.frames.size(), ds.frames.size());
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    ASSERT_TRUE(back.frames[i].pose);
    EXPECT_LT((back.frames[i].pose->matrix() - poses[i].matrix()).norm(), 1e-9);
  }
  EXPECT_EQ(back.load_frame(3).depth, ds.load_frame(3).depth);
  // Not over an existing dataset.
  EXPECT_THROW(write_dataset_with_poses(ds, poses, out), InputError);
}

TEST_F(SagFusion, FuseCliReportsEachGroupsCorrectionAndWritesTheRefinedDataset) {
  const std::string data = shared.file("sag2"), json = tmp.file("fuse.json");
  const std::string out = tmp.file("cli_refined");
  const testing::CliRun run = testing::run_cli(
      "fuse " + data + " --set fusion.voxel_mm=20 --json " + json + " --refined-dataset " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("refined by"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("after one rigid alignment"), std::string::npos) << run.out;
  const nlohmann::json j = nlohmann::json::parse(testing::slurp(json));
  EXPECT_TRUE(j["pose_refinement"]["ran"].get<bool>());
  ASSERT_EQ(j["poses"].size(), 3u);
  for (const auto& p : j["poses"]) {
    const auto& r = p["refinement"];
    ASSERT_TRUE(r.is_object()) << p.dump();
    EXPECT_GE(r["rotation_deg"].get<double>(), 0.0);
    EXPECT_LT(r["rotation_deg"].get<double>(), 2.0);
    EXPECT_LT(r["translation_mm"].get<double>(), 60.0);
    EXPECT_TRUE(r["constrained"].is_array());
    EXPECT_NE(std::find(r["constrained"].begin(), r["constrained"].end(), "yaw"), r["constrained"].end());
  }
  // The refined dataset is read by every command, with the poses the JSON reports.
  const Dataset back = read_dataset(out);
  const nlohmann::json& f0 = j["frames"][0];
  ASSERT_TRUE(back.frames[0].pose);
  EXPECT_LT((back.frames[0].pose->matrix() -
             isometry_from_json(f0["camera_to_world"], "test", "camera_to_world").matrix()).norm(), 1e-9);
  const testing::CliRun detect = testing::run_cli("detect " + out + " --quiet");
  EXPECT_EQ(detect.exit_code, 0) << detect.err;
  // Not refined: no correction, the given poses are the fused ones.
  const testing::CliRun plain = testing::run_cli("fuse " + data + " --set fusion.voxel_mm=20 --no-pose-refinement --json " + json);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const nlohmann::json k = nlohmann::json::parse(testing::slurp(json));
  EXPECT_FALSE(k["pose_refinement"]["ran"].get<bool>());
  for (const auto& p : k["poses"]) EXPECT_TRUE(p["refinement"].is_null());
  EXPECT_EQ(k["frames"][0]["camera_to_world"], k["frames"][0]["given_camera_to_world"]);
  // A refined dataset never overwrites anything.
  const testing::CliRun again = testing::run_cli("fuse " + data + " --set fusion.voxel_mm=20 --refined-dataset " + out);
  EXPECT_EQ(again.exit_code, 2);  // bad usage, refused before any work
  EXPECT_NE(again.err.find("must be new or empty"), std::string::npos) << again.err;
}

}  // namespace
}  // namespace tunnelmap
