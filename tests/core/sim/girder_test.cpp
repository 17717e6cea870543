// Tests of the simulator's whole-girder features (core/sim): odometry drift, long girders with
// diaphragms and manholes, their ground truth, curves, and the second noise model.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/io/dataset.h"
#include "core/sim/sensor_model.h"
#include "core/sim/sim_config_json.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/sim/sim_girder.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"
#include "tests/support/girder_walk_config.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path fresh_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() /
                     ("tunnelmap_girder_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

SimConfig exact(SimConfig c) {
  c.noise_scale = 0.0;
  c.dropout_scale = 0.0;
  c.quantize_disparity = false;
  return c;
}

// A walk of `stops` stations `step` metres apart from x = 0, one frame per stop, no jitter.
SimConfig walk_config(int stops, double step) {
  SimConfig c = SimConfig::from_preset("lab");
  SimWalk w;
  w.start_x_m = 0.0;
  w.end_x_m = step * (stops - 1);
  w.stops = stops;
  c.walk = w;
  c.frames = stops;
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  return c;
}

double rotation_angle(const Eigen::Matrix3d& R) { return Eigen::AngleAxisd(R).angle(); }

Eigen::Isometry3d pose_from_json(const json& a) {
  Eigen::Matrix4d M;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) M(r, c) = a.at(r * 4 + c).get<double>();
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

int run_cli_err(const std::string& args, std::string& err) {
  const fs::path err_file = fresh_dir("stderr");
  const int status = std::system((std::string(TUNNELMAP_CLI_PATH) + " " + args + " >/dev/null 2>" +
                                  err_file.string())
                                     .c_str());
  std::ifstream in(err_file);
  err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  fs::remove(err_file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// ---------------------------------------------------------------------------------------------
// Odometry drift

TEST(SimDriftTest, DriftGrowsAsTheSquareRootOfTheDistance) {
  // 10 stations 4 m apart; per-axis RMS of the translation error over many seeds must be
  // sigma * sqrt(s) and the rotation angle's RMS sigma_r * sqrt(3 s) at s = 4, 16 and 36 m.
  constexpr int kSeeds = 400;
  const double st = 6.0, sr = 0.12;  // mm and degrees per sqrt(m)
  const int groups[3] = {1, 4, 9};
  double sum_t2[3] = {0, 0, 0}, sum_r2[3] = {0, 0, 0};
  for (int seed = 1; seed <= kSeeds; ++seed) {
    SimConfig c = walk_config(10, 4.0);
    c.seed = static_cast<unsigned>(seed);
    c.drift_translation_mm_per_sqrt_m = st;
    c.drift_rotation_deg_per_sqrt_m = sr;
    const TunnelSimulator sim(c);
    for (int k = 0; k < 3; ++k) {
      const int i = groups[k];  // one frame per group
      ASSERT_NEAR(sim.travelled_m(i), 4.0 * i, 1e-9);
      const Eigen::Isometry3d truth = sim.pose(i), reported = sim.reported_pose(i);
      sum_t2[k] += (reported.translation() - truth.translation()).squaredNorm() * 1e6;
      const double a = rotation_angle(reported.linear() * truth.linear().transpose()) * 180.0 / M_PI;
      sum_r2[k] += a * a;
    }
    // The first station has no drift.
    EXPECT_TRUE(sim.reported_pose(0).isApprox(sim.pose(0), 1e-15));
  }
  for (int k = 0; k < 3; ++k) {
    const double s = 4.0 * groups[k];
    const double rms_t = std::sqrt(sum_t2[k] / (3.0 * kSeeds));  // per axis
    const double rms_r = std::sqrt(sum_r2[k] / kSeeds);
    std::printf("s = %4.0f m: translation RMS per axis %.2f mm (model %.2f), rotation RMS %.3f deg "
                "(model %.3f)\n",
                s, rms_t, st * std::sqrt(s), rms_r, sr * std::sqrt(3.0 * s));
    EXPECT_NEAR(rms_t / (st * std::sqrt(s)), 1.0, 0.10) << s;
    EXPECT_NEAR(rms_r / (sr * std::sqrt(3.0 * s)), 1.0, 0.10) << s;
  }
}

TEST(SimDriftTest, FramesOfOneStopShareTheDriftAndNoDriftMeansExactPoses) {
  SimConfig c = walk_config(4, 2.0);
  c.frames = 12;
  c.jitter_translation_m = 0.002;
  c.jitter_rotation_deg = 0.2;
  c.drift_translation_mm_per_sqrt_m = 10.0;
  c.drift_rotation_deg_per_sqrt_m = 0.2;
  const TunnelSimulator sim(c);
  for (int i = 0; i < sim.frame_count(); ++i) {
    const int g = sim.pose_group(i);
    const SimDrift& d = sim.drift(g);
    const Eigen::Isometry3d T = sim.pose(i), R = sim.reported_pose(i);
    EXPECT_TRUE((R.translation() - T.translation()).isApprox(d.translation, 1e-12) ||
                d.translation.norm() == 0.0);
    EXPECT_TRUE((R.linear() * T.linear().transpose()).isApprox(d.rotation, 1e-12));
    if (g > 0) {
      EXPECT_GT(d.translation.norm(), 0.0);
    }
  }
  // Same seed, same drift; the rendered images do not depend on the drift.
  SimConfig none = c;
  none.drift_translation_mm_per_sqrt_m = 0.0;
  none.drift_rotation_deg_per_sqrt_m = 0.0;
  const TunnelSimulator exact_sim(none);
  EXPECT_TRUE(exact_sim.reported_pose(7).isApprox(exact_sim.pose(7), 1e-15));
  EXPECT_TRUE(exact_sim.pose(7).isApprox(sim.pose(7), 1e-15));
  EXPECT_EQ(exact_sim.render(7).frame.depth, sim.render(7).frame.depth);
}

TEST(SimDriftTest, PoseTrueIsTheRenderedPoseAndPoseIsDrifted) {
  // Noise-free walk towards an end wall: the end wall's depth seen from pose_true agrees with
  // the depth image; seen from the drifted pose it does not.
  SimConfig c = exact(walk_config(3, 1.0));
  c.end_wall_distance_m = 2.5;
  c.drift_translation_mm_per_sqrt_m = 20.0;
  c.drift_rotation_deg_per_sqrt_m = 0.5;
  c.seed = 7;
  const fs::path dir = fresh_dir("drift");
  write_sim_dataset(dir.string(), c);
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  EXPECT_EQ(j.at("simulator").at("drift_translation_mm_per_sqrt_m").get<double>(), 20.0);
  int end_id = 0;
  for (const json& s : j.at("ground_truth").at("surfaces"))
    if (s.at("wall") == "end") end_id = s.at("id").get<int>();
  ASSERT_GT(end_id, 0);
  const Dataset ds = read_dataset(dir.string());
  const Intrinsics K = ds.intrinsics;
  const double end_x = 2.0 + 2.5;
  for (int i = 0; i < 3; ++i) {
    const json& fj = j.at("frames")[i];
    ASSERT_TRUE(fj.contains("pose_true"));
    const Eigen::Isometry3d truth = pose_from_json(fj.at("pose_true"));
    const Eigen::Isometry3d drifted = pose_from_json(fj.at("pose"));
    const DepthFrame depth = ds.load_frame(i);
    const std::vector<std::uint16_t> gt = ds.load_gt_surfaces(i);
    double worst_true = 0.0, worst_drifted = 0.0;
    int n = 0;
    for (int v = 0; v < depth.height; v += 4)
      for (int u = 0; u < depth.width; u += 4) {
        if (gt[v * depth.width + u] != end_id || depth.depth_m(u, v) <= 0.0f) continue;
        const double z = depth.depth_m(u, v);
        auto plane_depth = [&](const Eigen::Isometry3d& T) {
          const Eigen::Vector3d d = T.linear() * K.ray(u, v);  // camera z component 1
          return (end_x - T.translation().x()) / d.x();
        };
        worst_true = std::max(worst_true, std::abs(plane_depth(truth) - z));
        worst_drifted = std::max(worst_drifted, std::abs(plane_depth(drifted) - z));
        ++n;
      }
    ASSERT_GT(n, 100) << i;
    EXPECT_LT(worst_true, 0.0006) << i;  // millimetre rounding
    if (i > 0) {
      EXPECT_GT(worst_drifted, 0.005) << i;
    }
  }
  fs::remove_all(dir);
}

TEST(SimDriftTest, AnImuGivesGravityFromTheTrueCameraWithinItsNoiseWhateverTheDrift) {
  // A drifted walk of 12 stops with a 0.2 degree IMU: each frame's gravity lies within 1 degree
  // (5 sigma) of where things fall in the true camera, and the spread matches the noise;
  // without the IMU the frames carry none.
  SimConfig c = exact(walk_config(12, 0.5));
  c.end_wall_distance_m = 2.5;
  c.drift_rotation_deg_per_sqrt_m = 2.0;
  c.imu_gravity_deg = 0.2;
  const fs::path dir = fresh_dir("imu");
  write_sim_dataset(dir.string(), c);
  const Dataset ds = read_dataset(dir.string());
  double sum_sq = 0.0, drifted_worst = 0.0;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    ASSERT_TRUE(ds.frames[i].gravity) << i;
    const Eigen::Isometry3d truth = pose_from_json(ds.frames[i].raw.at("pose_true"));
    const Eigen::Vector3d down_true = truth.linear().transpose() * -Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d down_drifted = ds.frames[i].pose->linear().transpose() * -Eigen::Vector3d::UnitZ();
    const double off = std::acos(std::clamp(ds.frames[i].gravity->dot(down_true), -1.0, 1.0)) * 180.0 / M_PI;
    EXPECT_LT(off, 1.0) << i;
    sum_sq += off * off;
    drifted_worst = std::max(drifted_worst, std::acos(std::clamp(ds.frames[i].gravity->dot(down_drifted), -1.0, 1.0)) * 180.0 / M_PI);
  }
  // Two axes of 0.2 degrees: the tilt's RMS is 0.28 degrees.
  const double rms = std::sqrt(sum_sq / static_cast<double>(ds.frames.size()));
  EXPECT_GT(rms, 0.15);
  EXPECT_LT(rms, 0.45);
  EXPECT_GT(drifted_worst, 1.5);  // the drift tilts the given poses, not the IMU
  fs::remove_all(dir);
  c.imu_gravity_deg = 0.0;
  write_sim_dataset(dir.string(), c);
  EXPECT_FALSE(read_dataset(dir.string()).frames[0].gravity);
  fs::remove_all(dir);
}

TEST(SimDriftTest, ArmDriftMovesTheRobotBaseAndKeepsPoseTrue) {
  SimConfig c = walk_config(3, 0.5);
  c.walk->pose = SimCameraPose{0.0, 0.75, 0.0, -6.0, 0.0};
  c.arm_preset = "inchworm7";
  c.drift_translation_mm_per_sqrt_m = 10.0;
  c.drift_rotation_deg_per_sqrt_m = 0.2;
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(2);
  ASSERT_TRUE(f.arm);
  const SimDrift& d = sim.drift(2);
  EXPECT_TRUE(f.reported_base.translation().isApprox(f.arm->base.translation() + d.translation, 1e-12));
  EXPECT_TRUE(f.reported_pose.isApprox(sim.reported_pose(2), 1e-12));
  EXPECT_TRUE(f.frame.pose->isApprox(f.arm->true_pose, 1e-12));
  EXPECT_GT((f.reported_pose.translation() - f.arm->fk_pose.translation()).norm(), 1e-4);
}

TEST(SimDriftTest, CliDriftFlag) {
  const fs::path dir = fresh_dir("cli_drift");
  std::string err;
  EXPECT_EQ(run_cli_err("simulate " + dir.string() +
                            " --frames 4 --walk 0,3,4 --drift 6,0.12 --imu 0.1 --seed 3 --quiet",
                        err),
            0)
      << err;
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  EXPECT_EQ(j.at("simulator").at("drift_rotation_deg_per_sqrt_m").get<double>(), 0.12);
  EXPECT_TRUE(j.at("frames")[3].contains("pose_true"));
  EXPECT_NE(j.at("frames")[3].at("pose"), j.at("frames")[3].at("pose_true"));
  EXPECT_EQ(j.at("frames")[0].at("pose"), j.at("frames")[0].at("pose_true"));
  EXPECT_EQ(j.at("simulator").at("imu_gravity_deg").get<double>(), 0.1);
  EXPECT_EQ(j.at("frames")[3].at("gravity").size(), 3u);
  fs::remove_all(dir);
  for (const char* bad : {"--drift 6", "--drift 6,x", "--drift -1,0.1", "--drift 6,9", "--imu 11", "--imu -1"}) {
    EXPECT_EQ(run_cli_err("simulate " + dir.string() + " " + bad, err), 2) << bad;
    EXPECT_NE(err.find(std::string(bad).substr(0, 5)), std::string::npos) << bad << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << bad << ": " << err;
  }
  EXPECT_FALSE(fs::exists(dir));
}

// ---------------------------------------------------------------------------------------------
// Long girders, diaphragms and manholes

TEST(SimGirderTest, NoDiaphragmStandsWithinATenthOfAMetreOfTheManholePlate) {
  // The approach's manhole plate at 5 m is the diaphragm there: at a 4.96 m spacing the
  // diaphragm 4 cm before it is not built; at 4.8 m the two stand 20 cm apart, both built.
  SimConfig c = testing::girder_walk_config(30.0, 4.96, 10);
  c.manhole_distances_m = {5.0, 3.0, 1.8};
  std::vector<double> x = TunnelSimulator(c).diaphragms_x();
  ASSERT_EQ(x.size(), 5u);
  EXPECT_DOUBLE_EQ(x[0], 5.0);
  EXPECT_NEAR(x[1], 2 * 4.96, 1e-9);
  c.diaphragm_spacing_m = 4.8;
  x = TunnelSimulator(c).diaphragms_x();
  ASSERT_EQ(x.size(), 6u);
  EXPECT_NEAR(x[0], 4.8, 1e-9);
  EXPECT_DOUBLE_EQ(x[1], 5.0);
}

TEST(SimGirderTest, NoDiaphragmStandsWithinHalfASpacingOfTheEndWall) {
  // 30.5 m at 3.79 m: 8 x 3.79 = 30.32 would leave an 18 cm bay; the end bay takes it.
  std::vector<double> x = TunnelSimulator(testing::girder_walk_config(30.5, 3.79, 10)).diaphragms_x();
  ASSERT_EQ(x.size(), 7u);
  EXPECT_NEAR(x.back(), 7 * 3.79, 1e-9);
  // 30.5 m at 3.2 m: 9 x 3.2 = 28.8 leaves 1.7 m, more than half a spacing: built.
  x = TunnelSimulator(testing::girder_walk_config(30.5, 3.2, 10)).diaphragms_x();
  ASSERT_EQ(x.size(), 9u);
  EXPECT_NEAR(x.back(), 28.8, 1e-9);
}

sim::RayHit cast(const TunnelSimulator& sim, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
  return sim.geometry().cast(o, d.normalized());
}

std::string wall_of(const TunnelSimulator& sim, int id) {
  const SimSurface* s = sim.surface(id);
  return s ? s->name : id == kSimRivetId ? "rivet" : "none";
}

TEST(SimGirderTest, DiaphragmsEverySpacingAlongALongGirder) {
  const TunnelSimulator sim(testing::girder_walk_config(100.0, 4.0, 50));
  const std::vector<double> x = sim.diaphragms_x();
  ASSERT_EQ(x.size(), 24u);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_DOUBLE_EQ(x[i], 4.0 * (i + 1));
  const double cz = 0.5 * 1.20;
  // Along the axis through every opening to the end wall; back to the start wall.
  sim::RayHit h = cast(sim, {10.0, 0.0, cz}, {1, 0, 0});
  EXPECT_EQ(wall_of(sim, h.surface_id), "end");
  EXPECT_NEAR(h.t, 90.0, 1e-9);
  h = cast(sim, {10.0, 0.0, cz}, {-1, 0, 0});
  EXPECT_EQ(wall_of(sim, h.surface_id), "start");
  EXPECT_NEAR(h.t, 10.0, 1e-9);
  // Off the opening: the next plate, from either side.
  h = cast(sim, {10.0, 0.0, 0.1}, {1, 0, 0});
  EXPECT_EQ(wall_of(sim, h.surface_id), "diaphragm/2");
  EXPECT_NEAR(h.t, 2.0, 1e-9);
  h = cast(sim, {10.0, 0.0, 0.1}, {-1, 0, 0});
  EXPECT_EQ(wall_of(sim, h.surface_id), "diaphragm/1");
  EXPECT_NEAR(h.t, 2.0, 1e-9);
  // A ray climbing through the opening of plate 12 hits the roof beyond it.
  h = cast(sim, {10.0, 0.0, cz}, {1, 0, 0.1});
  EXPECT_EQ(wall_of(sim, h.surface_id).substr(0, 3), "top");
  EXPECT_GT(h.point.x(), 12.0);
}

TEST(SimGirderTest, RoundedRectangleLetsRaysThroughItsCornersWhereAnEllipseDoesNot) {
  SimConfig c = testing::girder_walk_config(12.0, 4.0, 4);
  c.manhole_width_m = 0.60;
  c.manhole_height_m = 0.80;
  c.manhole_centre_z_rel = 0.45;
  const double cz = 0.45 * 1.20;
  // Near the opening's corner (inside the rounded rectangle, outside the ellipse) and past
  // the rounding of a 5 cm corner (outside both).
  const Eigen::Vector3d corner(2.0, 0.27, cz + 0.37), beyond(2.0, 0.295, cz + 0.395);
  const Eigen::Vector3d middle(2.0, 0.0, cz + 0.39), low(2.0, -0.29, cz - 0.30);
  c.manhole_shape = "ellipse";
  {
    const TunnelSimulator sim(c);
    EXPECT_EQ(wall_of(sim, cast(sim, corner, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_EQ(wall_of(sim, cast(sim, beyond, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_NE(wall_of(sim, cast(sim, middle, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_EQ(wall_of(sim, cast(sim, low, {1, 0, 0}).surface_id), "diaphragm/0");
  }
  c.manhole_shape = "rounded_rectangle";
  c.manhole_corner_radius_m = 0.05;
  {
    const TunnelSimulator sim(c);
    EXPECT_NE(wall_of(sim, cast(sim, corner, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_EQ(wall_of(sim, cast(sim, beyond, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_NE(wall_of(sim, cast(sim, middle, {1, 0, 0}).surface_id), "diaphragm/0");
    EXPECT_NE(wall_of(sim, cast(sim, low, {1, 0, 0}).surface_id), "diaphragm/0");
    // Seen from behind the same.
    const Eigen::Vector3d back = corner + Eigen::Vector3d(4.0, 0.0, 0.0);
    EXPECT_NE(wall_of(sim, cast(sim, back, {-1, 0, 0}).surface_id), "diaphragm/0");
  }
  // The opening must fit its section: a centre too high is refused.
  c.manhole_centre_z_rel = 0.8;
  EXPECT_THROW(c.validate(), ParameterError);
}

TEST(SimGirderTest, WalkThroughTheManholesCentresTheCameraOnEachPlate) {
  SimConfig c = testing::girder_walk_config(12.0, 4.0, 23);  // stops every 0.5 m from 0.5 to 11.5
  c.walk->pose = SimCameraPose{0.2, 0.85, 0.0, -5.0, 0.0};
  c.manhole_centre_z_rel = 0.42;
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  const TunnelSimulator sim(c);
  int at_plate = 0, free = 0;
  for (int i = 0; i < sim.frame_count(); ++i) {
    const double x = sim.group_x(sim.pose_group(i));
    const Eigen::Vector3d t = sim.pose(i).translation();
    EXPECT_NEAR(t.x(), x, 1e-12);
    const double d = std::min(std::abs(x - 4.0), std::abs(x - 8.0));
    if (d <= 0.5) {
      EXPECT_NEAR(t.y(), 0.0, 1e-12) << x;
      EXPECT_NEAR(t.z(), 0.42 * 1.20, 1e-12) << x;
      ++at_plate;
    } else if (d >= 1.5) {
      EXPECT_NEAR(t.y(), 0.2 * 0.84, 1e-12) << x;
      EXPECT_NEAR(t.z(), 0.85 * 1.20, 1e-12) << x;
      ++free;
    } else {
      EXPECT_GT(t.z(), 0.42 * 1.20) << x;
      EXPECT_LT(t.z(), 0.85 * 1.20) << x;
    }
  }
  EXPECT_EQ(at_plate, 6);  // 3.5, 4, 4.5, 7.5, 8, 8.5
  EXPECT_GT(free, 4);
}

TEST(SimGirderTest, TheStopNearestEachCompartmentsMiddlePastAPlateLooksBack) {
  // Stops every 0.5 m from 0.5 to 11.5; plates at 4 and 8: compartments 4-8 and 8-11.5 (the
  // last stop ends the last one). The first compartment is seen looking ahead.
  std::vector<double> stops;
  for (int g = 0; g <= 22; ++g) stops.push_back(0.5 + 0.5 * g);
  const std::vector<bool> back = sim::look_back_stops(stops, {4.0, 8.0});
  std::vector<double> back_x;
  for (std::size_t g = 0; g < stops.size(); ++g)
    if (back[g]) back_x.push_back(stops[g]);
  EXPECT_EQ(back_x, (std::vector<double>{6.0, 9.5}));  // 9.5 and 10 are as near 9.75: the first
  // A compartment no stop stands in has none; the last stop may look back; no plates, none.
  EXPECT_EQ(sim::look_back_stops({1.0, 2.0, 9.0}, {4.0, 8.0}), (std::vector<bool>{false, false, true}));
  EXPECT_EQ(sim::look_back_stops(stops, {}), std::vector<bool>(stops.size(), false));
  // A diaphragm with a plate 0.32 m behind it: no room to look back between them; past the
  // plate, the stop nearest the middle of 4.32-7.0.
  EXPECT_EQ(sim::look_back_stops({3.5, 4.1, 4.2, 5.0, 6.0, 7.0}, {4.0, 4.32}),
            (std::vector<bool>{false, false, false, false, true, false}));
}

TEST(SimGirderTest, ALookBackStopSeesThePlateItClimbedThroughAndTheWallsJustPastIt) {
  SimConfig c = testing::girder_walk_config(12.0, 4.0, 23);
  c.walk->look_back = true;
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  const TunnelSimulator sim(c);
  int looked_back = 0;
  for (int i = 0; i < sim.frame_count(); ++i) {
    const double x = sim.group_x(sim.pose_group(i));
    const Eigen::Vector3d view = sim.pose(i).linear().col(2);  // the camera's optical axis
    if (!sim.looks_back(sim.pose_group(i))) {
      EXPECT_GT(view.x(), 0.99) << x;
      continue;
    }
    ++looked_back;
    EXPECT_LT(view.x(), -0.99) << x;
    // It sees the plate behind it and the walls up to that plate.
    const SimFrame f = sim.render(i);
    const double plate = x < 8.0 ? 4.0 : 8.0;
    double nearest_wall_x = 1e9;
    int plate_pixels = 0;
    for (int v = 0; v < f.frame.height; ++v)
      for (int u = 0; u < f.frame.width; ++u) {
        const SimSurface* s = sim.surface(f.surface_id[static_cast<std::size_t>(v) * f.frame.width + u]);
        if (!s || f.frame.depth_m(u, v) <= 0.0f) continue;
        const Eigen::Vector3d w =
            sim.pose(i) * f.frame.intrinsics.backproject(u, v, f.frame.depth_m(u, v)).cast<double>();
        if (s->wall == "diaphragm" && std::abs(w.x() - plate) < 0.05) ++plate_pixels;
        if (s->wall == "left" || s->wall == "right") nearest_wall_x = std::min(nearest_wall_x, w.x());
      }
    EXPECT_GT(plate_pixels, 10000) << x;
    EXPECT_LT(nearest_wall_x, plate + 0.6) << x;  // the forward frames start about 1 m past it
  }
  EXPECT_EQ(looked_back, 2);  // the stops at 6 m and 9.5 m
  EXPECT_TRUE(sim_config_from_json(sim_config_to_json(c), "test").walk->look_back);
  // A walk that looks back runs forward, past plates.
  SimConfig backwards = c;
  std::swap(backwards.walk->start_x_m, backwards.walk->end_x_m);
  EXPECT_THROW(TunnelSimulator{backwards}, ParameterError);
  SimConfig no_plates = c;
  no_plates.diaphragm_spacing_m = 0.0;
  EXPECT_THROW(TunnelSimulator{no_plates}, ParameterError);
}

// ---------------------------------------------------------------------------------------------
// Ground truth of the girder

TEST(SimGirderTest, GroundTruthListsCentrelineDiaphragmsAndCompartments) {
  SimConfig c = testing::girder_walk_config(12.0, 4.0, 3);
  c.manhole_shape = "rounded_rectangle";
  c.manhole_corner_radius_m = 0.08;
  const fs::path dir = fresh_dir("truth");
  write_sim_dataset(dir.string(), c);
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& g = j.at("ground_truth").at("girder");
  EXPECT_EQ(g.at("length_m").get<double>(), 12.0);
  const json& line = g.at("centreline");
  ASSERT_EQ(line.size(), 121u);
  for (std::size_t i = 0; i < line.size(); i += 10) {
    EXPECT_NEAR(line[i].at("station_m").get<double>(), 0.1 * i, 1e-9);
    EXPECT_NEAR(line[i].at("point")[0].get<double>(), 0.1 * i, 1e-9);
    EXPECT_NEAR(line[i].at("point")[1].get<double>(), 0.0, 1e-12);
    EXPECT_NEAR(line[i].at("point")[2].get<double>(), 0.60, 1e-12);
  }
  const json& plates = g.at("diaphragms");
  ASSERT_EQ(plates.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(plates[k].at("station_m").get<double>(), 4.0 * (k + 1));
    EXPECT_EQ(plates[k].at("normal"), json::array({1.0, 0.0, 0.0}));
    const json& m = plates[k].at("manhole");
    EXPECT_EQ(m.at("shape"), "rounded_rectangle");
    EXPECT_EQ(m.at("width_m").get<double>(), 0.45);
    EXPECT_EQ(m.at("height_m").get<double>(), 0.70);
    EXPECT_EQ(m.at("corner_radius_m").get<double>(), 0.08);
    EXPECT_NEAR(m.at("center")[0].get<double>(), 4.0 * (k + 1), 1e-12);
    EXPECT_NEAR(m.at("center")[2].get<double>(), 0.60, 1e-12);
  }
  const json& rooms = g.at("compartments");
  ASSERT_EQ(rooms.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(rooms[k].at("from_m").get<double>(), 4.0 * k);
    EXPECT_EQ(rooms[k].at("to_m").get<double>(), 4.0 * (k + 1));
    EXPECT_EQ(rooms[k].at("width_m").get<double>(), 0.84);
    EXPECT_EQ(rooms[k].at("height_m").get<double>(), 1.20);
  }
  for (const json& f : j.at("frames")) {
    ASSERT_TRUE(f.contains("pose_true"));
    EXPECT_EQ(f.at("pose"), f.at("pose_true"));  // no drift
  }
  // The existing truth stays.
  EXPECT_EQ(j.at("ground_truth").at("diaphragms_x_m"), json::array({4.0, 8.0}));
  EXPECT_EQ(j.at("ground_truth").at("width_m").get<double>(), 0.84);
  // The settings read back.
  const SimConfig back = sim_config_from_json(j.at("simulator"), "test");
  EXPECT_EQ(*back.girder_length_m, 12.0);
  EXPECT_EQ(back.diaphragm_spacing_m, 4.0);
  EXPECT_EQ(back.manhole_shape, "rounded_rectangle");
  EXPECT_TRUE(back.walk->through_openings);
  fs::remove_all(dir);
}

// The truth's frame at a world point: station, lateral offset (along the level left direction
// rolled by the cross-fall) and height offset from the truth centreline.
struct TruthOffset {
  double station, y, z;
};

TruthOffset truth_offset(const json& line, double cross_fall_deg, const Eigen::Vector3d& p) {
  std::size_t best = 1;
  double best_d = 1e300;
  std::vector<Eigen::Vector3d> c(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) {
    c[i] = Eigen::Vector3d(line[i]["point"][0].get<double>(), line[i]["point"][1].get<double>(),
                           line[i]["point"][2].get<double>());
  }
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    const double d = (p - c[i]).squaredNorm();
    if (d < best_d) best_d = d, best = i;
  }
  // The segment on the side of the point's foot.
  const Eigen::Vector3d fwd = (c[best + 1] - c[best]).normalized();
  const std::size_t a = (p - c[best]).dot(fwd) >= 0.0 ? best : best - 1;
  const Eigen::Vector3d t = (c[a + 1] - c[a]).normalized();
  const double along = (p - c[a]).dot(t);
  const Eigen::Vector3d lat = p - (c[a] + along * t);
  const double cf = cross_fall_deg * M_PI / 180.0;
  const Eigen::Vector3d y0 = Eigen::Vector3d::UnitZ().cross(t).normalized();
  const Eigen::Vector3d z0 = t.cross(y0);
  const Eigen::Vector3d left = std::cos(cf) * y0 + std::sin(cf) * z0;
  const Eigen::Vector3d up = -std::sin(cf) * y0 + std::cos(cf) * z0;
  return {line[a]["station_m"].get<double>() + along, lat.dot(left), lat.dot(up)};
}

SimConfig curved_config(int frames) {
  SimConfig c = testing::girder_walk_config(16.0, 4.0, frames);
  c.curve_radius_m = 150.0;
  c.gradient_pct = 4.0;
  c.cross_fall_deg = 3.0;
  c.rust_patches_per_wall = 0;
  return c;
}

Eigen::Vector3d world_point(const DepthFrame& f, const Eigen::Isometry3d& T, int u, int v) {
  return T * f.intrinsics.backproject(u, v, f.depth_m(u, v)).cast<double>();
}

// Of every `step`-th pixel on an edge band of the frames of `dir` (written from `c`, a girder
// 0.84 x 1.20 m), the largest distance from where the truth puts that wall; `count` receives
// how many were looked at.
double worst_edge_band_offset(const SimConfig& c, const fs::path& dir, double cross_fall_deg, int step, int& count) {
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& line = j.at("ground_truth").at("girder").at("centreline");
  const Dataset ds = read_dataset(dir.string());
  const TunnelSimulator sim(c);
  double worst = 0.0;
  count = 0;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const DepthFrame f = ds.load_frame(i);
    const std::vector<std::uint16_t> gt = ds.load_gt_surfaces(i);
    const Eigen::Isometry3d T = pose_from_json(j.at("frames")[i].at("pose_true"));
    for (int v = 0; v < f.height; v += step)
      for (int u = 0; u < f.width; u += step) {
        const SimSurface* s = sim.surface(gt[v * f.width + u]);
        if (!s || s->zone != "edge" || f.depth_m(u, v) <= 0.0f) continue;
        const TruthOffset o = truth_offset(line, cross_fall_deg, world_point(f, T, u, v));
        double err = 0.0;
        if (s->wall == "left") err = o.y - 0.42;
        if (s->wall == "right") err = o.y + 0.42;
        if (s->wall == "top") err = o.z - 0.60;
        if (s->wall == "bottom") err = o.z + 0.60;
        worst = std::max(worst, std::abs(err));
        ++count;
      }
  }
  return worst;
}

TEST(SimGirderTest, CurvedGirderWallPointsLieOnTheTruthWalls) {
  // Noise-free frames along a girder curving at R = 150 m, rising at 4 %, rolled by 3 deg:
  // every edge-band point is W/2 or H/2 from the truth centreline in the truth frame.
  SimConfig c = exact(curved_config(5));
  const fs::path dir = fresh_dir("curve");
  write_sim_dataset(dir.string(), c);
  int n = 0;
  const double worst = worst_edge_band_offset(c, dir, 3.0, 3, n);
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& line = j.at("ground_truth").at("girder").at("centreline");
  std::printf("curved girder: %d edge-band points, worst offset from the truth walls %.2f mm\n", n,
              worst * 1000.0);
  EXPECT_GT(n, 5000);
  EXPECT_LT(worst, 0.002);
  // The centreline really curves: 16 m of a 150 m radius turn by 6.1 deg and rise 0.64 m.
  const json& last = line.back().at("point");
  EXPECT_NEAR(last[2].get<double>() - line[0].at("point")[2].get<double>(), 0.04 * 16.0, 0.01);
  EXPECT_NEAR(last[1].get<double>(), 150.0 * (1.0 - std::cos(16.0 / 150.0)), 0.03);
  fs::remove_all(dir);
}

// Heading in plan (rad, left positive) and slope of the truth centreline's chord between two
// of its stations.
struct Chord {
  double heading, slope;
};
Chord chord(const json& line, double from_m, double to_m) {
  const auto at = [&](double s) {
    const json& p = line.at(static_cast<std::size_t>(std::lround(s / 0.1))).at("point");
    return Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  const Eigen::Vector3d d = at(to_m) - at(from_m);
  return {std::atan2(d.y(), d.x()), d.z() / d.head<2>().norm()};
}

TEST(SimGirderTest, ATransitionCurveAndAVerticalCurveBendTheGirderAsDesigned) {
  // Straight to 6 m, then a 12 m transition into a 150 m curve to the right; the gradient
  // falls from +2 % by 0.1 % per metre (a crest, R = 1000 m). Plates every 4 m are joints.
  SimConfig c = exact(testing::girder_walk_config(30.0, 4.0, 3));
  c.curve_radius_m = -150.0;
  c.transition_start_m = 6.0;
  c.transition_m = 12.0;
  c.gradient_pct = 2.0;
  c.vertical_radius_m = -1000.0;
  c.cross_fall_deg = 2.0;
  c.rust_patches_per_wall = 0;
  const fs::path dir = fresh_dir("transition");
  write_sim_dataset(dir.string(), c);
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& line = j.at("ground_truth").at("girder").at("centreline");
  // Straight before the transition.
  EXPECT_NEAR(chord(line, 0.0, 4.0).heading, 0.0, 1e-9);
  // In the transition the heading grows as the square of the distance into it (the chord
  // from 2 to 6 m in: the mean of u^2 over it is 52/3), and after it the circle turns evenly.
  EXPECT_NEAR(chord(line, 8.0, 12.0).heading, -(52.0 / 3.0) / (2.0 * 150.0 * 12.0), 2e-4);
  EXPECT_NEAR(chord(line, 24.0, 28.0).heading, -(12.0 / (2.0 * 150.0) + 8.0 / 150.0), 2e-4);
  // The gradient at 2 m and at 26 m.
  EXPECT_NEAR(chord(line, 0.0, 4.0).slope, 0.02 - 2.0 / 1000.0, 1e-4);
  EXPECT_NEAR(chord(line, 24.0, 28.0).slope, 0.02 - 26.0 / 1000.0, 1e-4);
  // The frames see walls where the truth puts them.
  int n = 0;
  const double worst = worst_edge_band_offset(c, dir, 2.0, 4, n);
  EXPECT_GT(n, 1000);
  EXPECT_LT(worst, 0.002);
  fs::remove_all(dir);
}

TEST(SimGirderTest, DiaphragmTruthMatchesTheRenderedPlate) {
  // Straight and curved: the pixels of each diaphragm lie on its truth plane, at its station,
  // and the pixels seen through the opening are inside the truth opening.
  for (const bool curved : {false, true}) {
    SimConfig c = exact(curved ? curved_config(4) : testing::girder_walk_config(16.0, 4.0, 4));
    c.manhole_shape = "rounded_rectangle";
    c.manhole_centre_z_rel = 0.45;
    c.walk->start_x_m = 1.0;  // stops at 1, 5.8, 10.7: 1.3-3 m before a plate; 15.5: the end
    c.walk->end_x_m = 15.5;
    const fs::path dir = fresh_dir(curved ? "plate_curved" : "plate");
    write_sim_dataset(dir.string(), c);
    std::ifstream in(dir / "dataset.json");
    const json j = json::parse(in);
    const json& plates = j.at("ground_truth").at("girder").at("diaphragms");
    const json& line = j.at("ground_truth").at("girder").at("centreline");
    const Dataset ds = read_dataset(dir.string());
    int on_plate = 0;
    double worst = 0.0, worst_station = 0.0;
    for (std::size_t i = 0; i < ds.frames.size(); ++i) {
      const DepthFrame f = ds.load_frame(i);
      const std::vector<std::uint16_t> gt = ds.load_gt_surfaces(i);
      const Eigen::Isometry3d T = pose_from_json(j.at("frames")[i].at("pose_true"));
      for (const json& p : plates) {
        const int id = p.at("surface_id").get<int>();
        const Eigen::Vector3d point(p["point"][0].get<double>(), p["point"][1].get<double>(),
                                    p["point"][2].get<double>());
        const Eigen::Vector3d normal(p["normal"][0].get<double>(), p["normal"][1].get<double>(),
                                     p["normal"][2].get<double>());
        for (int v = 0; v < f.height; v += 2)
          for (int u = 0; u < f.width; u += 2) {
            if (gt[v * f.width + u] != id || f.depth_m(u, v) <= 0.0f) continue;
            const Eigen::Vector3d q = world_point(f, T, u, v);
            worst = std::max(worst, std::abs(normal.dot(q - point)));
            const TruthOffset o = truth_offset(line, curved ? 3.0 : 0.0, q);
            worst_station = std::max(worst_station, std::abs(o.station - p.at("station_m").get<double>()));
            ++on_plate;
          }
      }
    }
    std::printf("%s girder: %d plate pixels, worst distance to the truth plate %.2f mm, station "
                "%.2f mm\n",
                curved ? "curved" : "straight", on_plate, worst * 1000.0, worst_station * 1000.0);
    EXPECT_GT(on_plate, 20000);
    EXPECT_LT(worst, 0.0006);        // depth rounded to whole millimetres
    // A mitre plate leans by half the deflection (4 m / 150 m / 2) across the section.
    EXPECT_LT(worst_station, curved ? 0.42 * std::tan(4.0 / 150.0 / 2.0) + 0.001 : 0.001);
    fs::remove_all(dir);
  }
}

TEST(SimGirderTest, HundredMetreGirderOfAThousandFramesRenders) {
  // 1,000 stops along a 100 m girder, R = 150 m, 4 % gradient; 20 of its frames rendered.
  SimConfig c = testing::girder_walk_config(100.0, 4.0, 1000);
  c.curve_radius_m = 150.0;
  c.gradient_pct = 4.0;
  const auto t0 = std::chrono::steady_clock::now();
  const TunnelSimulator sim(c);
  std::set<int> plates_seen;
  for (int i = 0; i < 1000; i += 50) {
    const SimFrame f = sim.render(i);
    int valid = 0;
    for (float d : f.frame.depth) valid += d > 0.0f;
    EXPECT_GT(valid, f.frame.width * f.frame.height / 2) << i;
    for (std::uint16_t id : f.surface_id) {
      const SimSurface* s = sim.surface(id);
      if (s && s->wall == "diaphragm") plates_seen.insert(id);
    }
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("100 m girder: 20 frames in %.0f ms (%.0f ms per frame)\n", ms, ms / 20.0);
  EXPECT_GE(plates_seen.size(), 12u);
}

TEST(SimGirderTest, CliGirderFlags) {
  const fs::path dir = fresh_dir("cli_girder");
  std::string err;
  EXPECT_EQ(run_cli_err("simulate " + dir.string() +
                            " --preset field --girder 12 --diaphragm-spacing 4 --frames 3"
                            " --manhole rounded_rectangle,0.5,0.7,0.45,0.1 --curve-radius -150"
                            " --gradient-pct 4 --cross-fall-deg 2 --drift 6,0.12 --transition 3,5"
                            " --vertical-radius -2000 --look-back --quiet",
                        err),
            0)
      << err;
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& sim = j.at("simulator");
  EXPECT_EQ(sim.at("girder_length_m").get<double>(), 12.0);
  EXPECT_EQ(sim.at("diaphragm_spacing_m").get<double>(), 4.0);
  EXPECT_EQ(sim.at("manhole_shape"), "rounded_rectangle");
  EXPECT_EQ(sim.at("manhole_corner_radius_m").get<double>(), 0.1);
  EXPECT_EQ(sim.at("curve_radius_m").get<double>(), -150.0);
  EXPECT_EQ(sim.at("transition_start_m").get<double>(), 3.0);
  EXPECT_EQ(sim.at("transition_m").get<double>(), 5.0);
  EXPECT_EQ(sim.at("vertical_radius_m").get<double>(), -2000.0);
  EXPECT_EQ(j.at("ground_truth").at("girder").at("vertical_radius_m").get<double>(), -2000.0);
  EXPECT_EQ(sim.at("walk").at("stops"), 3);
  EXPECT_EQ(sim.at("walk").at("through_openings"), true);
  EXPECT_EQ(sim.at("walk").at("look_back"), true);
  EXPECT_EQ(j.at("ground_truth").at("girder").at("diaphragms").size(), 2u);
  // A right-hand curve: the centreline ends at negative y.
  EXPECT_LT(j.at("ground_truth").at("girder").at("centreline").back().at("point")[1].get<double>(), -0.1);
  fs::remove_all(dir);

  const std::pair<const char*, const char*> bad[] = {
      {"--diaphragm-spacing 4", "--diaphragm-spacing"},
      {"--girder 0.5", "--girder"},
      {"--girder 10 --diaphragm-spacing 0.1", "--diaphragm-spacing"},
      {"--girder 10 --distance-to-manhole 3", "--distance-to-manhole"},
      {"--manhole triangle,0.5,0.7,0.5", "--manhole"},
      {"--manhole ellipse,0.5,0.7", "--manhole"},
      {"--manhole ellipse,0.5,0.7,0.5,0.1", "--manhole"},
      {"--manhole rounded_rectangle,0.5,0.7,0.5,0.4", "--manhole"},
      {"--girder 10 --diaphragm-spacing 4 --manhole ellipse,0.5,0.7,0.9", "manhole_centre_z_rel"},
      {"--curve-radius 10", "--curve-radius"},
      {"--gradient-pct 20", "--gradient-pct"},
      {"--cross-fall-deg 11", "--cross-fall-deg"},
      {"--transition 3,5", "--transition"},
      {"--curve-radius 150 --transition 3", "--transition"},
      {"--curve-radius 150 --transition 3,-5", "--transition"},
      {"--curve-radius 150 --transition 3,0", "--transition"},
      {"--vertical-radius 50", "--vertical-radius"},
      {"--look-back", "--look-back"},
  };
  for (const auto& [args, flag] : bad) {
    EXPECT_EQ(run_cli_err("simulate " + dir.string() + " " + args, err), 2) << args;
    EXPECT_NE(err.find(flag), std::string::npos) << args << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << ": " << err;
  }
  EXPECT_FALSE(fs::exists(dir));
}

// ---------------------------------------------------------------------------------------------
// The second noise model

// Camera at x = 0 looking along +X at a manhole plate 2 m ahead (depth 2 m on the whole plate),
// the end wall 3 m behind it; no jitter, dropouts or rust.
SimConfig plate_view(const std::string& model) {
  SimConfig c = SimConfig::from_preset("lab");
  c.frames = 1;
  c.poses = {{0.0, 0.5, 0.0, 0.0, 0.0}};
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  c.dropout_scale = 0.0;
  c.rust_patches_per_wall = 0;
  c.distance_to_manhole_m = 2.0;
  c.noise_model = model;
  return c;
}

struct PlateStats {
  int n = 0, flying = 0, distinct = 0;
  double mean = 0.0, sd = 0.0;
};

PlateStats plate_stats(const SimConfig& c) {
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  int plate = 0;
  for (const SimSurface& s : sim.surfaces())
    if (s.wall == "manhole") plate = s.id;
  const int W = f.frame.width;
  PlateStats st;
  double sum = 0.0, sum2 = 0.0;
  std::set<float> values;
  for (int v = 1; v + 1 < f.frame.height; ++v)
    for (int u = 1; u + 1 < W; ++u) {
      const float d = f.frame.depth[v * W + u];
      if (f.surface_id[v * W + u] != plate || d <= 0.0f) continue;
      if (d > 2030.0f) ++st.flying;  // > 6 sigma behind the plate
      bool interior = true;
      for (int dv = -2; dv <= 2; ++dv)
        for (int du = -2; du <= 2; ++du)
          if (v + dv >= 0 && v + dv < f.frame.height && u + du >= 0 && u + du < W)
            interior &= f.surface_id[(v + dv) * W + u + du] == plate;
      if (!interior) continue;
      const double r = d / 1000.0 - 2.0;
      sum += r;
      sum2 += r * r;
      values.insert(d);
      ++st.n;
    }
  st.mean = sum / st.n;
  st.sd = std::sqrt(sum2 / st.n - st.mean * st.mean);
  st.distinct = static_cast<int>(values.size());
  return st;
}

TEST(SimNoiseTest, TimeOfFlightNoiseIsLinearInDepthUnquantisedWithFlyingPixels) {
  const SimConfig tof = plate_view("tof");
  const PlateStats t = plate_stats(tof);
  const double model = sim::tof_sigma_m(2.0, 0.0, tof.tof_sigma_m, tof.tof_sigma_per_m);
  std::printf("ToF plate at 2 m: %d pixels, sd %.2f mm (model %.2f at normal incidence), mean "
              "%.2f mm, %d distinct depths, %d flying pixels\n",
              t.n, t.sd * 1000.0, model * 1000.0, t.mean * 1000.0, t.distinct, t.flying);
  ASSERT_GT(t.n, 20000);
  EXPECT_NEAR(t.sd / model, 1.0, 0.15);  // incidence up to 25 deg adds < 5 %
  EXPECT_LT(std::abs(t.mean), 0.0005);
  EXPECT_GT(t.distinct, 15);  // whole millimetres, no disparity steps
  EXPECT_GT(t.flying, 100);   // around the opening's rim
  // Linear in depth: sigma(4 m) - sigma(2 m) = sigma(2 m) - sigma(0).
  EXPECT_NEAR(sim::tof_sigma_m(4.0, 0.0, 0.001, 0.002) - sim::tof_sigma_m(2.0, 0.0, 0.001, 0.002),
              0.004, 1e-12);
  // No flying pixels without their probability; none with the structured-light model's steps.
  SimConfig still = tof;
  still.tof_flying_pixel_probability = 0.0;
  EXPECT_EQ(plate_stats(still).flying, 0);
  const PlateStats sl = plate_stats(plate_view("structured_light"));
  std::printf("structured light plate at 2 m: sd %.2f mm, %d distinct depths\n", sl.sd * 1000.0,
              sl.distinct);
  EXPECT_LE(sl.distinct, 8);  // quantised to 11.7 mm disparity steps at 2 m
  // The model reads back from the dataset's settings, and bad names are refused.
  const SimConfig back = sim_config_from_json(sim_config_to_json(tof), "test");
  EXPECT_EQ(back.noise_model, "tof");
  SimConfig bad = tof;
  bad.noise_model = "lidar";
  EXPECT_THROW(bad.validate(), ParameterError);
  std::string err;
  const fs::path dir = fresh_dir("cli_noise");
  EXPECT_EQ(run_cli_err("simulate " + dir.string() + " --noise-model lidar", err), 2);
  EXPECT_NE(err.find("--noise-model"), std::string::npos) << err;
  EXPECT_EQ(run_cli_err("simulate " + dir.string() + " --frames 1 --noise-model tof --quiet", err), 0)
      << err;
  std::ifstream in(dir / "dataset.json");
  EXPECT_EQ(json::parse(in).at("simulator").at("noise_model"), "tof");
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Longitudinal stiffeners

TEST(SimStiffenerTest, FlatBarsStandOutOfTheWallsAndTheirPixelsLieOnTheirFaces) {
  SimConfig c = exact(SimConfig::from_preset("lab"));  // 0.82 x 1.30 m, plates 8 mm
  c.frames = 1;
  c.poses = {{0.0, 0.5, 0.0, 0.0, 0.0}};
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  // On the left middle plate, on the floor's middle plate, on the roof's left edge band.
  c.stiffeners = {{kSimLeft, 0.65}, {kSimBottom, 0.0}, {kSimTop, 0.3}};
  const TunnelSimulator sim(c);
  // Across to the left wall at the bar's height: its top face 8 mm + 0.1 m out of the wall.
  sim::RayHit h = cast(sim, {1.0, 0.0, 0.65}, {0, 1, 0});
  EXPECT_EQ(wall_of(sim, h.surface_id), "left/stiffener0/top");
  EXPECT_NEAR(h.t, 0.41 - 0.108, 1e-12);
  h = cast(sim, {1.0, 0.0, 0.80}, {0, 1, 0});  // above it: the plate
  EXPECT_EQ(wall_of(sim, h.surface_id), "left/middle");
  h = cast(sim, {1.0, 0.35, 0.9}, {0, 0, -1});  // down along the wall: the bar's upper side
  EXPECT_EQ(wall_of(sim, h.surface_id), "left/stiffener0/side_top");
  EXPECT_NEAR(h.point.z(), 0.655, 1e-12);
  h = cast(sim, {1.0, 0.30, 0.6}, {0, 0, 1});  // up to the roof's edge band: a bar of 0.1 m
  EXPECT_EQ(wall_of(sim, h.surface_id), "top/stiffener2/top");
  EXPECT_NEAR(h.point.z(), 1.30 - 0.10, 1e-12);
  // Rendered: every bar is seen, every pixel on its face's plane.
  const SimFrame f = sim.render(0);
  std::map<std::string, int> count;
  double worst = 0.0;
  for (int v = 0; v < f.frame.height; ++v)
    for (int u = 0; u < f.frame.width; ++u) {
      const SimSurface* s = sim.surface(f.surface_id[v * f.frame.width + u]);
      if (!s || s->zone != "stiffener" || f.frame.depth_m(u, v) <= 0.0f) continue;
      const Eigen::Vector3d p = *f.frame.pose * f.frame.intrinsics.backproject(u, v, f.frame.depth_m(u, v)).cast<double>();
      worst = std::max(worst, std::abs(s->distance(p)));
      ++count[s->name.substr(0, s->name.find("/", s->name.find("stiffener")))];
    }
  for (const char* bar : {"left/stiffener0", "bottom/stiffener1", "top/stiffener2"})
    EXPECT_GT(count[bar], 300) << bar;
  EXPECT_LT(worst, 0.0006);
  // Without stiffeners the ids of the constant tunnel are unchanged; with them they follow.
  EXPECT_EQ(sim.surfaces()[19].name, "bottom/step_left");
  EXPECT_EQ(sim.surfaces()[20].name, "left/stiffener0/top");
  // Settings round trip; validation.
  const SimConfig back = sim_config_from_json(sim_config_to_json(c), "test");
  ASSERT_EQ(back.stiffeners.size(), 3u);
  EXPECT_EQ(back.stiffeners[2].wall, kSimTop);
  EXPECT_EQ(back.stiffeners[2].position_m, 0.3);
  SimConfig bad = c;
  bad.stiffeners = {{kSimLeft, 1.5}};
  EXPECT_THROW(bad.validate(), ParameterError);
  // CLI.
  const fs::path dir = fresh_dir("cli_stiffeners");
  std::string err;
  EXPECT_EQ(run_cli_err("simulate " + dir.string() +
                            " --frames 1 --walk 0,0,1 --stiffeners left:0.65,right:0.4"
                            " --stiffener-size 0.12,0.012 --quiet",
                        err),
            0)
      << err;
  std::ifstream in(dir / "dataset.json");
  const json j = json::parse(in);
  const json& st = j.at("ground_truth").at("girder").at("stiffeners");
  ASSERT_EQ(st.size(), 2u);
  EXPECT_EQ(st[1].at("wall"), "right");
  EXPECT_EQ(st[1].at("height_m").get<double>(), 0.12);
  fs::remove_all(dir);
  for (const auto& [args, flag] : std::vector<std::pair<std::string, std::string>>{
           {"--stiffeners middle:0.5", "--stiffeners"},
           {"--stiffeners left:x", "--stiffeners"},
           {"--stiffeners left:0.5 --stiffener-size 0.1", "--stiffener-size"},
           {"--stiffener-size 0.1,0.01", "--stiffener-size"},
           {"--stiffeners left:2", "stiffener position_m"}}) {
    EXPECT_EQ(run_cli_err("simulate " + dir.string() + " " + args, err), 2) << args;
    EXPECT_NE(err.find(flag), std::string::npos) << args << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << ": " << err;
  }
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace tunnelmap
