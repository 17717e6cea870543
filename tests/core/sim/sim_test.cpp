// Tests of the simulated tunnel depth camera (core/sim) and its dataset writer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <cstdio>
#include <stdexcept>
#include <sys/wait.h>

#include "core/io/dataset.h"
#include "core/sim/sensor_model.h"
#include "core/sim/sim_config_json.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/sim/sim_spec_parse.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;

// One frame looking straight along the tunnel from its centre, no jitter.
SimConfig straight_config() {
  SimConfig c = SimConfig::from_preset("lab");
  c.frames = 1;
  c.poses = {{0.0, 0.5, 0.0, 0.0, 0.0}};
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  return c;
}

SimConfig exact(SimConfig c) {
  c.noise_scale = 0.0;
  c.dropout_scale = 0.0;
  c.quantize_disparity = false;
  return c;
}

struct PixelTruth {
  double z_true;  // depth of the pixel's ray on its ground-truth plane
  double theta;   // incidence angle there
};

// Ground truth of pixel (u, v) from its planar surface id.
PixelTruth truth(const TunnelSimulator& sim, const SimFrame& f, const SimSurface& s, int u,
                 int v) {
  const Eigen::Isometry3d T = *f.frame.pose;
  const Eigen::Vector3d dir = (T.linear() * f.frame.intrinsics.ray(u, v)).normalized();
  const double t = -s.distance(T.translation()) / s.normal_world.dot(dir);
  return {t * dir.dot(T.linear().col(2)), std::acos(std::abs(s.normal_world.dot(dir)))};
}

Eigen::Vector3d world_point(const SimFrame& f, int u, int v) {
  const double z = f.frame.depth_m(u, v);
  return *f.frame.pose * f.frame.intrinsics.backproject(u, v, z).cast<double>();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() /
                     ("tunnelmap_sim_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

TEST(SimTest, NoiseFreePointsLieOnTheirTruePlanesAndWidthIsExact) {
  const TunnelSimulator sim(exact(straight_config()));
  const SimFrame f = sim.render(0);
  std::map<int, int> count;
  double max_err = 0.0, left_y = 0.0, right_y = 0.0;
  int left_n = 0, right_n = 0;
  for (int v = 0; v < f.frame.height; ++v)
    for (int u = 0; u < f.frame.width; ++u) {
      const int id = f.surface_id[v * f.frame.width + u];
      const SimSurface* s = sim.surface(id);
      if (!s || f.frame.depth_m(u, v) <= 0.0f) continue;
      const Eigen::Vector3d p = world_point(f, u, v);
      max_err = std::max(max_err, std::abs(s->distance(p)));
      ++count[id];
      if (s->zone == "edge" && s->wall == "left") left_y += p.y(), ++left_n;
      if (s->zone == "edge" && s->wall == "right") right_y += p.y(), ++right_n;
    }
  EXPECT_LT(max_err, 0.0005);
  ASSERT_GT(left_n, 1000);
  ASSERT_GT(right_n, 1000);
  EXPECT_NEAR(left_y / left_n - right_y / right_n, 0.82, 0.001);
  // Every wall zone and the end wall are visible; rivets too.
  for (const SimSurface& s : sim.surfaces())
    if (s.zone == "edge" || s.zone == "middle" || s.wall == "end") {
      EXPECT_GT(count[s.id], 200) << s.name;
    }
  EXPECT_GT(std::count(f.surface_id.begin(), f.surface_id.end(), kSimRivetId), 100);
}

TEST(SimTest, MiddlePlatesProtrudeByTheirThickness) {
  SimConfig c = exact(straight_config());
  c.plate_thickness_m = {0.006, 0.008, 0.010, 0.012};
  const TunnelSimulator sim(c);
  for (const SimSurface& s : sim.surfaces()) {
    if (s.zone != "middle") continue;
    const SimSurface* edge = nullptr;
    for (const SimSurface& e : sim.surfaces())
      if (e.wall == s.wall && e.zone == "edge") edge = &e;
    ASSERT_NE(edge, nullptr);
    const double expected = s.wall == "left" ? 0.006 : s.wall == "right" ? 0.008
                            : s.wall == "top" ? 0.010 : 0.012;
    EXPECT_NEAR(edge->offset_world - s.offset_world, expected, 1e-12) << s.name;
  }
}

TEST(SimTest, SameSeedSameDepthOtherSeedDifferent) {
  SimConfig c = SimConfig::from_preset("field");
  c.frames = 3;
  const SimFrame a = TunnelSimulator(c).render(1);
  const SimFrame b = TunnelSimulator(c).render(1);
  EXPECT_EQ(a.frame.depth, b.frame.depth);
  EXPECT_EQ(a.frame.rgb, b.frame.rgb);
  EXPECT_EQ(a.surface_id, b.surface_id);
  c.seed = 2;
  const SimFrame d = TunnelSimulator(c).render(1);
  EXPECT_NE(a.frame.depth, d.frame.depth);
  // Frames of one pose differ (jitter and noise).
  EXPECT_NE(TunnelSimulator(c).render(0).frame.depth, d.frame.depth);
}

TEST(SimTest, AxialNoiseMatchesTheModelAtTwoMetres) {
  SimConfig c = straight_config();
  c.dropout_scale = 0.0;
  c.quantize_disparity = false;
  c.rust_patches_per_wall = 0;
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  const int W = f.frame.width;
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int v = 1; v + 1 < f.frame.height; ++v)
    for (int u = 1; u + 1 < W; ++u) {
      const int id = f.surface_id[v * W + u];
      const SimSurface* s = sim.surface(id);
      if (!s || s->zone == "step" || f.frame.depth_m(u, v) <= 0.0f) continue;
      bool interior = true;  // away from zone borders, where lateral noise swaps surfaces
      for (int dv = -1; dv <= 1; ++dv)
        for (int du = -1; du <= 1; ++du) interior &= f.surface_id[(v + dv) * W + u + du] == id;
      if (!interior) continue;
      const PixelTruth t = truth(sim, f, *s, u, v);
      if (t.z_true < 1.8 || t.z_true > 2.2) continue;
      const double r = (f.frame.depth_m(u, v) - t.z_true) / sim::axial_sigma_m(t.z_true, t.theta);
      sum += r;
      sum2 += r * r;
      ++n;
    }
  ASSERT_GT(n, 500);
  const double mean = sum / n, std_ratio = std::sqrt(sum2 / n - mean * mean);
  EXPECT_GT(std_ratio, 1.0 / 1.5);
  EXPECT_LT(std_ratio, 1.5);
  EXPECT_LT(std::abs(mean), 0.15);
  std::printf("2 m wall pixels: %d, residual / model sigma: std %.3f mean %.3f\n", n, std_ratio,
              mean);
}

TEST(SimTest, QuantisedDepthStaysWithinHalfADisparityStep) {
  SimConfig c = exact(straight_config());
  c.quantize_disparity = true;
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  int n = 0;
  for (int v = 0; v < f.frame.height; v += 2)
    for (int u = 0; u < f.frame.width; u += 2) {
      const SimSurface* s = sim.surface(f.surface_id[v * f.frame.width + u]);
      if (!s || f.frame.depth_m(u, v) <= 0.0f) continue;
      const PixelTruth t = truth(sim, f, *s, u, v);
      const double step = sim::quantization_step_m(t.z_true, 570.3, 0.075, 8);
      EXPECT_LE(std::abs(f.frame.depth_m(u, v) - t.z_true), 0.5 * step * 1.05 + 0.0005);
      ++n;
    }
  EXPECT_GT(n, 10000);
  // The step at 2 m is z^2 / (fx b 8) = 11.7 mm.
  EXPECT_NEAR(sim::quantization_step_m(2.0, 570.3, 0.075, 8), 0.01169, 0.0001);
}

TEST(SimTest, DropoutRisesWithIncidenceAngle) {
  SimConfig c = straight_config();
  c.noise_scale = 0.0;
  c.rust_patches_per_wall = 0;
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  int bins_total[4] = {0, 0, 0, 0}, bins_drop[4] = {0, 0, 0, 0};
  for (int v = 0; v < f.frame.height; ++v)
    for (int u = 0; u < f.frame.width; ++u) {
      const SimSurface* s = sim.surface(f.surface_id[v * f.frame.width + u]);
      if (!s) continue;
      const PixelTruth t = truth(sim, f, *s, u, v);
      if (t.z_true < 0.5 || t.z_true > 5.8) continue;
      const double deg = t.theta * 180.0 / M_PI;
      const int bin = deg < 60 ? 0 : deg < 75 ? 1 : deg < 80 ? 2 : deg < 84 ? 3 : -1;
      if (bin < 0) continue;
      ++bins_total[bin];
      bins_drop[bin] += f.frame.depth_m(u, v) <= 0.0f;
    }
  double rate[4];
  for (int b = 0; b < 4; ++b) {
    ASSERT_GT(bins_total[b], 300) << "bin " << b;
    rate[b] = static_cast<double>(bins_drop[b]) / bins_total[b];
  }
  std::printf("dropout rate by incidence <60/60-75/75-80/80-84 deg: %.3f %.3f %.3f %.3f\n",
              rate[0], rate[1], rate[2], rate[3]);
  EXPECT_LT(rate[0], 0.03);  // speckle only (1 %)
  EXPECT_GT(rate[1], rate[0]);
  EXPECT_GT(rate[2], rate[1] + 0.1);
  EXPECT_GT(rate[3], rate[2] + 0.1);
}

TEST(SimTest, NoDepthBeyondTheRangeLimit) {
  SimConfig c = straight_config();
  c.dropout_scale = 0.0;
  c.end_wall_distance_m = 9.0;  // beyond the 6 m range limit
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  int far = 0, far_measured = 0, near_measured = 0;
  for (int v = 0; v < f.frame.height; ++v)
    for (int u = 0; u < f.frame.width; ++u) {
      const SimSurface* s = sim.surface(f.surface_id[v * f.frame.width + u]);
      if (!s) continue;
      const PixelTruth t = truth(sim, f, *s, u, v);
      const bool measured = f.frame.depth_m(u, v) > 0.0f;
      if (t.z_true > 6.3) {
        ++far;
        far_measured += measured;
      }
      if (t.z_true < 5.0) near_measured += measured;
      if (measured) {
        EXPECT_LE(f.frame.depth_m(u, v), 6.0f);
      }
    }
  EXPECT_GT(far, 1000);
  EXPECT_EQ(far_measured, 0);
  EXPECT_GT(near_measured, 100000);
}

TEST(SimTest, ManholePlateBlocksAllButItsOpening) {
  SimConfig c = exact(SimConfig::from_preset("field"));
  c.frames = 1;
  c.distance_to_manhole_m = 1.8;
  c.jitter_translation_m = 0.0;
  c.jitter_rotation_deg = 0.0;
  c.poses = {{0.0, 0.5, 0.0, 0.0, 0.0}};
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  int plate_id = 0;
  for (const SimSurface& s : sim.surfaces())
    if (s.wall == "manhole") plate_id = s.id;
  ASSERT_GT(plate_id, 0);
  EXPECT_GT(std::count(f.surface_id.begin(), f.surface_id.end(), plate_id), 20000);
  // The centre pixel looks through the opening: the plate at 1.8 m does not stop it.
  const int centre = 240 * 640 + 320;
  EXPECT_NE(f.surface_id[centre], plate_id);
  EXPECT_TRUE(f.frame.depth[centre] == 0.0f || f.frame.depth_m(320, 240) > 1.81f);
  // Plate pixels are at the plate's depth.
  for (int u = 0; u < 640; u += 7) {
    if (f.surface_id[20 * 640 + u] != plate_id) continue;
    EXPECT_NEAR(f.frame.depth_m(u, 20), 1.8, 0.0006);
  }
  EXPECT_EQ(*sim.distance_to_manhole(0), 1.8);
}

TEST(SimTest, FieldFramesCycleThroughTheManholeDistances) {
  SimConfig c = SimConfig::from_preset("field");
  const TunnelSimulator sim(c);
  EXPECT_EQ(sim.frame_count(), 30);
  EXPECT_EQ(*sim.distance_to_manhole(0), 5.0);
  EXPECT_EQ(*sim.distance_to_manhole(10), 3.0);
  EXPECT_EQ(*sim.distance_to_manhole(29), 1.8);
  // The camera stands `distance` in front of the plate.
  EXPECT_NEAR(*sim.manhole_x() - sim.pose(15).translation().x(), 3.0, 0.02);
  EXPECT_FALSE(TunnelSimulator(SimConfig::from_preset("lab")).distance_to_manhole(0));
}

TEST(SimTest, NeutralPoseLooksAlongTheTunnel) {
  const Eigen::Matrix3d R = TunnelSimulator::camera_rotation(0, 0, 0);
  EXPECT_TRUE(R.col(2).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(R.col(0).isApprox(-Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(R.col(1).isApprox(-Eigen::Vector3d::UnitZ()));
  const Eigen::Matrix3d down = TunnelSimulator::camera_rotation(0, -15, 0);
  EXPECT_NEAR(down.col(2).z(), -std::sin(15 * M_PI / 180), 1e-12);  // pitched down
}

TEST(SimTest, PresetsAndRangeChecks) {
  EXPECT_THROW(SimConfig::from_preset("tunnel"), ParameterError);
  SimConfig c;
  EXPECT_NO_THROW(c.validate());
  c.width_m = 100.0;
  EXPECT_THROW(c.validate(), ParameterError);
  c = SimConfig();
  c.noise_scale = -1.0;
  EXPECT_THROW(TunnelSimulator{c}, ParameterError);
  const SimConfig lab = SimConfig::from_preset("lab"), field = SimConfig::from_preset("field");
  EXPECT_EQ(lab.width_m, 0.82);
  EXPECT_EQ(lab.height_m, 1.30);
  EXPECT_EQ(field.width_m, 0.84);
  EXPECT_EQ(field.height_m, 1.20);
}

TEST(SimTest, ConfigJsonRoundTrips) {
  SimConfig c = SimConfig::from_preset("field");
  c.seed = 77;
  c.distance_to_manhole_m = 2.5;
  c.plate_thickness_m[kSimTop] = 0.011;
  const nlohmann::json j = sim_config_to_json(c);
  const SimConfig back = sim_config_from_json(j, "test");
  EXPECT_EQ(sim_config_to_json(back), j);
  nlohmann::json bad = j;
  bad["width_m"] = "wide";
  EXPECT_THROW(sim_config_from_json(bad, "x.json"), InputError);
}

TEST(SimTest, WritesADatasetFolderAndRefusesAForeignOne) {
  const fs::path dir = fresh_dir("write");
  SimConfig c = SimConfig::from_preset("field");
  c.frames = 2;
  write_sim_dataset(dir.string(), c);
  for (const char* f : {"dataset.json", "depth/000000.png", "rgb/000000.png", "gt/000000.png",
                        "depth/000001.png", "rgb/000001.png", "gt/000001.png"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  std::ifstream in(dir / "dataset.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("format"), "tunnelmap-dataset/1");
  EXPECT_EQ(j.at("intrinsics").at("fx").get<double>(), 570.3);
  EXPECT_EQ(j.at("intrinsics").at("width").get<int>(), 640);
  EXPECT_EQ(j.at("depth_scale").get<double>(), 1000.0);
  EXPECT_EQ(j.at("up"), nlohmann::json::array({0, 0, 1}));
  ASSERT_EQ(j.at("frames").size(), 2u);
  const nlohmann::json& f0 = j.at("frames")[0];
  EXPECT_EQ(f0.at("depth"), "depth/000000.png");
  EXPECT_EQ(f0.at("gt_surfaces"), "gt/000000.png");
  EXPECT_EQ(f0.at("pose").size(), 16u);
  EXPECT_EQ(f0.at("pose")[15].get<double>(), 1.0);
  EXPECT_EQ(f0.at("distance_to_manhole_m").get<double>(), 5.0);
  EXPECT_EQ(j.at("ground_truth").at("width_m").get<double>(), 0.84);
  EXPECT_EQ(j.at("ground_truth").at("height_m").get<double>(), 1.20);
  const nlohmann::json& s0 = j.at("ground_truth").at("surfaces")[0];
  EXPECT_EQ(s0.at("id"), 1);
  EXPECT_EQ(s0.at("name"), "left/edge_bottom");
  EXPECT_EQ(s0.at("normal").size(), 3u);
  EXPECT_EQ(j.at("simulator").at("seed"), 1);

  // The PNGs hold exactly what the simulator rendered.
  const SimFrame f = TunnelSimulator(c).render(1);
  const cv::Mat depth = cv::imread((dir / "depth/000001.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat gt = cv::imread((dir / "gt/000001.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_16UC1);
  ASSERT_EQ(gt.type(), CV_16UC1);
  EXPECT_EQ(depth.at<std::uint16_t>(300, 100), static_cast<std::uint16_t>(f.frame.depth[300 * 640 + 100]));
  int diff = 0;
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u)
      diff += depth.at<std::uint16_t>(v, u) != f.frame.depth[v * 640 + u] ||
              gt.at<std::uint16_t>(v, u) != f.surface_id[v * 640 + u];
  EXPECT_EQ(diff, 0);

  // The core/io reader accepts the folder and returns the same frame.
  const Dataset ds = read_dataset(dir.string());
  ASSERT_EQ(ds.frames.size(), 2u);
  EXPECT_EQ(*ds.gt_width_m, 0.84);
  const DepthFrame back = ds.load_frame(1);
  ASSERT_EQ(back.depth.size(), f.frame.depth.size());
  EXPECT_NEAR(back.depth_m(100, 300), f.frame.depth_m(100, 300), 1e-6);
  EXPECT_EQ(back.rgb, f.frame.rgb);
  EXPECT_TRUE(back.pose->isApprox(*f.frame.pose, 1e-12));
  EXPECT_EQ(ds.load_gt_surfaces(1), f.surface_id);

  // Writing again over our own dataset is allowed; a foreign folder is refused untouched.
  EXPECT_NO_THROW(write_sim_dataset(dir.string(), c));
  const fs::path foreign = fresh_dir("foreign");
  fs::create_directories(foreign);
  std::ofstream(foreign / "notes.txt") << "mine";
  EXPECT_THROW(write_sim_dataset(foreign.string(), c), OutputPathError);  // bad usage
  EXPECT_FALSE(fs::exists(foreign / "dataset.json"));
  EXPECT_FALSE(fs::exists(foreign / "depth"));
  fs::remove_all(dir);
  fs::remove_all(foreign);
}

int run_cli(const std::string& args) {
  const int status = std::system((std::string(TUNNELMAP_CLI_PATH) + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SimTest, CliSimulateWritesADatasetAndRejectsAbsurdValues) {
  const fs::path dir = fresh_dir("cli");
  EXPECT_EQ(run_cli("simulate " + dir.string() + " --width 100"), 2);
  EXPECT_EQ(run_cli("simulate " + dir.string() + " --frames 0"), 2);
  EXPECT_EQ(run_cli("simulate " + dir.string() + " --preset mine"), 2);
  EXPECT_FALSE(fs::exists(dir));
  EXPECT_EQ(run_cli("simulate " + dir.string() +
                    " --preset field --frames 1 --distance-to-manhole 3 --seed 5 --quiet"),
            0);
  EXPECT_TRUE(fs::is_regular_file(dir / "dataset.json"));
  EXPECT_TRUE(fs::is_regular_file(dir / "depth/000000.png"));
  fs::remove_all(dir);
}


// Three sections: 0.84 x 1.30 on [.., 1.5), 0.80 x 1.28 on [1.5, 3.0), 0.82 x 1.32 on [3.0, ..);
// no end wall, so rays along the axis leave the tunnel unless something stops them.
SimConfig sectioned_config() {
  SimConfig c = exact(straight_config());
  c.sections = {{1.5, 0.84, 1.30}, {1.5, 0.80, 1.28}, {2.0, 0.82, 1.32}};
  c.end_wall_distance_m.reset();
  return c;
}

const SimSurface& named(const TunnelSimulator& sim, const std::string& name) {
  for (const SimSurface& s : sim.surfaces())
    if (s.name == name) return s;
  throw std::runtime_error("no surface " + name);
}

sim::RayHit cast(const TunnelSimulator& sim, Eigen::Vector3d o, Eigen::Vector3d d) {
  return sim.geometry().cast(o, d.normalized());
}

TEST(SimSectionsTest, RaysHitEachSectionsWallsAtItsOwnSize) {
  const TunnelSimulator sim(sectioned_config());
  // Straight across: the left middle plate (8 mm thick) of each section.
  sim::RayHit h = cast(sim, {0.5, 0.0, 0.65}, Eigen::Vector3d::UnitY());
  EXPECT_EQ(h.surface_id, 2);  // section 0 keeps the constant tunnel's ids
  EXPECT_NEAR(h.point.y(), 0.42 - 0.008, 1e-12);
  EXPECT_EQ(h.section, 0);
  h = cast(sim, {2.0, 0.0, 0.65}, Eigen::Vector3d::UnitY());
  EXPECT_EQ(h.surface_id, named(sim, "section1/left/middle").id);
  EXPECT_EQ(h.surface_id, 22);
  EXPECT_NEAR(h.point.y(), 0.40 - 0.008, 1e-12);
  EXPECT_EQ(h.section, 1);
  // Edge band of section 1 (outer plane) and the roof of section 2.
  h = cast(sim, {2.0, 0.0, 0.05}, Eigen::Vector3d::UnitY());
  EXPECT_EQ(h.surface_id, named(sim, "section1/left/edge_bottom").id);
  EXPECT_NEAR(h.point.y(), 0.40, 1e-12);
  h = cast(sim, {4.0, 0.0, 0.3}, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(h.surface_id, named(sim, "section2/top/middle").id);
  EXPECT_EQ(h.surface_id, 48);
  EXPECT_NEAR(h.point.z(), 1.32 - 0.008, 1e-12);
  EXPECT_NEAR(h.t, 1.32 - 0.008 - 0.3, 1e-12);
  // Slanting to the left from x = 1: it would meet section 0's plate at x = 5.12 and section
  // 1's at 4.92, but both have ended; it meets section 2's (y = 0.402) at x = 5.02.
  h = cast(sim, {1.0, 0.0, 0.65}, {1.0, 0.1, 0.0});
  EXPECT_EQ(h.surface_id, named(sim, "section2/left/middle").id);
  EXPECT_NEAR(h.point.x(), 5.02, 1e-9);
  EXPECT_NEAR(h.point.y(), 0.402, 1e-12);
  EXPECT_NEAR(h.t, std::hypot(4.02, 0.402), 1e-9);
  // The ground-truth planes follow the sections.
  EXPECT_NEAR(named(sim, "section1/left/middle").offset_world, 0.40 - 0.008, 1e-12);
  EXPECT_EQ(named(sim, "section1/left/middle").section, 1);
  EXPECT_NEAR(named(sim, "section2/bottom/middle").offset_world, -0.008, 1e-12);
}

TEST(SimSectionsTest, JointFacesStopRaysThatMissTheNextSection) {
  const TunnelSimulator sim(sectioned_config());
  const SimSurface& j0 = named(sim, "joint/0");
  const SimSurface& j1 = named(sim, "joint/1");
  EXPECT_EQ(j0.wall, "joint");
  EXPECT_EQ(j0.zone, "");
  EXPECT_EQ(j0.id, 61);  // after the 3 x 20 wall surfaces
  EXPECT_EQ(j1.id, 62);
  // Shrinking joint at 1.5 faces back (-X), growing joint at 3.0 faces forward (+X).
  EXPECT_TRUE(j0.normal_world.isApprox(-Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(j0.offset_world, 1.5, 1e-12);
  EXPECT_TRUE(j1.normal_world.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(j1.offset_world, -3.0, 1e-12);
  // Along the axis just under section 0's roof plate (z 1.292): section 1's roof plate is at
  // 1.272, so the ray stops on the joint face at x = 1.5.
  sim::RayHit h = cast(sim, {0.5, 0.0, 1.29}, Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, j0.id);
  EXPECT_NEAR(h.t, 1.0, 1e-12);
  EXPECT_NEAR(h.point.x(), 1.5, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(-Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(j0.distance(h.point), 0.0, 1e-12);
  // Beside the left plate (y 0.412 < 0.42) but outside section 1 (0.40): the joint again.
  h = cast(sim, {0.2, 0.41, 0.65}, Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, j0.id);
  EXPECT_NEAR(h.t, 1.3, 1e-12);
  // Looking back from section 2 under its roof (1.312): section 1 is lower, joint 1 at x = 3.
  h = cast(sim, {4.0, 0.0, 1.30}, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, j1.id);
  EXPECT_NEAR(h.t, 1.0, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Eigen::Vector3d::UnitX()));
  // Down the centre line nothing stops the ray (no end wall); into a larger section neither.
  EXPECT_FALSE(cast(sim, {0.5, 0.0, 0.65}, Eigen::Vector3d::UnitX()).hit());
  EXPECT_FALSE(cast(sim, {2.0, 0.0, 1.27}, Eigen::Vector3d::UnitX()).hit());
}

TEST(SimSectionsTest, WidthAndHeightAtAndAroundJoints) {
  const TunnelSimulator sim(sectioned_config());
  EXPECT_EQ(sim.joints_x(), (std::vector<double>{1.5, 3.0}));
  EXPECT_EQ(sim.width_at(-100.0), 0.84);  // the first section continues before its start
  EXPECT_EQ(sim.width_at(1.5 - 1e-9), 0.84);
  EXPECT_EQ(sim.width_at(1.5), 0.80);  // a joint belongs to the section after it
  EXPECT_EQ(sim.height_at(1.5), 1.28);
  EXPECT_EQ(sim.height_at(3.0 - 1e-9), 1.28);
  EXPECT_EQ(sim.width_at(3.0), 0.82);
  EXPECT_EQ(sim.height_at(3.0), 1.32);
  EXPECT_EQ(sim.height_at(100.0), 1.32);  // the last one continues after its end
  SimConfig c = sectioned_config();
  c.sections_start_x_m = -1.0;
  const TunnelSimulator shifted(c);
  EXPECT_EQ(shifted.joints_x(), (std::vector<double>{0.5, 2.0}));
  EXPECT_EQ(shifted.width_at(0.49), 0.84);
  EXPECT_EQ(shifted.width_at(0.5), 0.80);
  const TunnelSimulator constant(straight_config());
  EXPECT_TRUE(constant.joints_x().empty());
  EXPECT_EQ(constant.width_at(12.0), 0.82);
  EXPECT_EQ(constant.height_at(-3.0), 1.30);
}

TEST(SimSectionsTest, SurfaceIdsOfTheConstantTunnelAreUnchanged) {
  SimConfig c = SimConfig::from_preset("field");
  const TunnelSimulator sim(c);
  ASSERT_EQ(sim.surfaces().size(), 21u);  // 12 zones, 8 steps, manhole
  EXPECT_EQ(sim.surfaces()[0].name, "left/edge_bottom");
  EXPECT_EQ(sim.surfaces()[11].name, "bottom/edge_left");
  EXPECT_EQ(sim.surfaces()[12].name, "left/step_bottom");
  EXPECT_EQ(sim.surfaces()[20].name, "manhole");
  EXPECT_EQ(sim.surfaces()[20].id, 21);
  // Diaphragms come after the manhole plate, the end wall last.
  c.diaphragm_x_m = {7.0, 9.0};
  c.end_wall_distance_m = 6.0;
  const TunnelSimulator more(c);
  ASSERT_EQ(more.surfaces().size(), 24u);
  EXPECT_EQ(more.surfaces()[20].name, "manhole");
  EXPECT_EQ(more.surfaces()[21].name, "diaphragm/0");
  EXPECT_EQ(more.surfaces()[21].id, 22);
  EXPECT_EQ(more.surfaces()[22].name, "diaphragm/1");
  EXPECT_EQ(more.surfaces()[23].name, "end");
  EXPECT_EQ(more.diaphragms_x(), (std::vector<double>{5.0, 7.0, 9.0}));
  // Without the new fields the simulator JSON has no new keys.
  const nlohmann::json j = sim_config_to_json(SimConfig::from_preset("lab"));
  EXPECT_FALSE(j.contains("sections"));
  EXPECT_FALSE(j.contains("diaphragm_x_m"));
  EXPECT_FALSE(j.contains("walk"));
}

TEST(SimSectionsTest, DiaphragmsBlockAllButTheirOpeningFromBothSides) {
  SimConfig c = sectioned_config();
  c.diaphragm_x_m = {0.8, 2.5};
  const TunnelSimulator sim(c);
  const SimSurface& d0 = named(sim, "diaphragm/0");
  const SimSurface& d1 = named(sim, "diaphragm/1");
  EXPECT_EQ(d0.wall, "diaphragm");
  EXPECT_EQ(d0.id, 63);  // after the walls and the two joints
  EXPECT_EQ(d1.id, 64);
  EXPECT_NEAR(d1.offset_world, 2.5, 1e-12);
  // Opening 0.45 x 0.70 m centred at half height: z 0.65 +- 0.35 in section 0.
  sim::RayHit h = cast(sim, {0.3, 0.0, 1.05}, Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, d0.id);
  EXPECT_NEAR(h.t, 0.5, 1e-12);
  EXPECT_EQ(cast(sim, {0.3, 0.0, 0.95}, Eigen::Vector3d::UnitX()).surface_id, 0);
  EXPECT_EQ(cast(sim, {0.3, 0.2, 0.65}, Eigen::Vector3d::UnitX()).surface_id, 0);
  EXPECT_EQ(cast(sim, {0.3, 0.23, 0.65}, Eigen::Vector3d::UnitX()).surface_id, d0.id);
  // Seen from behind: the same plate, its normal towards the camera.
  h = cast(sim, {2.0, 0.0, 1.05}, -Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, d0.id);
  EXPECT_NEAR(h.t, 1.2, 1e-12);
  EXPECT_TRUE(h.normal.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(h.plane_offset, -0.8, 1e-12);
  // In section 1 (height 1.28) the opening is centred at z = 0.64: 0.98 is inside, 1.00 not.
  EXPECT_EQ(cast(sim, {2.0, 0.0, 0.98}, Eigen::Vector3d::UnitX()).surface_id, 0);
  h = cast(sim, {2.0, 0.0, 1.00}, Eigen::Vector3d::UnitX());
  EXPECT_EQ(h.surface_id, d1.id);
  EXPECT_NEAR(h.point.x(), 2.5, 1e-12);
}

TEST(SimSectionsTest, RenderedPixelsLieOnTheirSectionsPlanes) {
  SimConfig c = sectioned_config();
  c.poses = {{0.0, 0.5, 0.0, -5.0, 0.0}};
  c.end_wall_distance_m = 5.0;
  c.diaphragm_x_m = {4.2};
  const TunnelSimulator sim(c);
  const SimFrame f = sim.render(0);
  std::map<int, int> count;
  double max_err = 0.0;
  for (int v = 0; v < f.frame.height; ++v)
    for (int u = 0; u < f.frame.width; ++u) {
      const SimSurface* s = sim.surface(f.surface_id[v * f.frame.width + u]);
      if (!s || f.frame.depth_m(u, v) <= 0.0f) continue;
      max_err = std::max(max_err, std::abs(s->distance(world_point(f, u, v))));
      ++count[s->id];
    }
  EXPECT_LT(max_err, 0.0006);  // depth rounded to whole millimetres, plates seen obliquely
  for (const char* name : {"section0/left/middle", "section1/left/middle", "section2/left/middle",
                           "section1/top/middle", "joint/0", "diaphragm/0"})
    EXPECT_GT(count[named(sim, name).id], 100) << name;
}

TEST(SimWalkTest, WalkPlacesOnePoseGroupPerStation) {
  SimConfig c = sectioned_config();
  c.frames = 10;
  c.walk = SimWalk{0.2, 3.0, 5, {0.1, 0.9, 0.0, -4.0, 2.0}};
  const TunnelSimulator sim(c);
  EXPECT_EQ(sim.group_count(), 5);
  const double xs[5] = {0.2, 0.9, 1.6, 2.3, 3.0};
  for (int i = 0; i < 10; ++i) {
    const int g = i / 2;
    EXPECT_EQ(sim.pose_group(i), g);
    EXPECT_NEAR(sim.group_x(g), xs[g], 1e-12);
    const Eigen::Vector3d p = sim.pose(i).translation();
    EXPECT_NEAR(p.x(), xs[g], 1e-12);
    // Relative to the station's own cross-section.
    EXPECT_NEAR(p.y(), 0.1 * sim.width_at(xs[g]), 1e-12);
    EXPECT_NEAR(p.z(), 0.9 * sim.height_at(xs[g]), 1e-12);
  }
  EXPECT_NEAR(sim.pose(0).translation().z(), 1.17, 1e-12);
  EXPECT_NEAR(sim.pose(5).translation().z(), 0.9 * 1.28, 1e-12);
  EXPECT_NEAR(sim.pose(9).translation().z(), 0.9 * 1.32, 1e-12);
  EXPECT_TRUE(sim.pose(3).linear().isApprox(TunnelSimulator::camera_rotation(0.0, -4.0, 2.0)));
  EXPECT_EQ(sim.group_x(4), 3.0);  // the last stop exactly at the end
  // With a manhole plate: each station's distance to it, only in front of it.
  c.distance_to_manhole_m = 2.0;
  const TunnelSimulator with_plate(c);
  EXPECT_NEAR(*with_plate.distance_to_manhole(0), 1.8, 1e-12);
  EXPECT_NEAR(*with_plate.distance_to_manhole(3), 1.1, 1e-12);
  EXPECT_FALSE(with_plate.distance_to_manhole(9));
  // One stop: every frame at the start.
  c.walk->stops = 1;
  EXPECT_NEAR(TunnelSimulator(c).pose(9).translation().x(), 0.2, 1e-12);
}

TEST(SimWalkTest, ApproachLosesTheFloorInFrontOfThePlate) {
  // Camera just under the roof, level; the walk ends 1.8 m in front of a diaphragm at 5 m.
  SimConfig c = exact(straight_config());
  c.frames = 2;
  c.diaphragm_x_m = {5.0};
  c.end_wall_distance_m.reset();
  c.walk = SimWalk{0.2, 3.2, 2, {0.0, 0.9, 0.0, 0.0, 0.0}};
  const TunnelSimulator sim(c);
  const int plate = named(sim, "diaphragm/0").id;
  int floor_in_front[2] = {0, 0}, plate_pixels[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const SimFrame f = sim.render(i);
    for (int v = 0; v < f.frame.height; ++v)
      for (int u = 0; u < f.frame.width; ++u) {
        const int id = f.surface_id[v * f.frame.width + u];
        if (id == plate) {
          ++plate_pixels[i];
          if (i == 1 && u % 9 == 0 && v % 9 == 0) {
            EXPECT_NEAR(f.frame.depth_m(u, v), 1.8, 0.0006);
          }
        }
        const SimSurface* s = sim.surface(id);
        if (!s || s->wall != "bottom" || f.frame.depth_m(u, v) <= 0.0f) continue;
        if (world_point(f, u, v).x() < 5.0) ++floor_in_front[i];
      }
  }
  EXPECT_GT(floor_in_front[0], 5000);  // 4.8 m away the floor shows from x = 3.0 to the plate
  EXPECT_EQ(floor_in_front[1], 0);     // 1.8 m away it would only show from x = 6.0
  EXPECT_GT(plate_pixels[1], plate_pixels[0]);
}

TEST(SimWalkTest, ArmFollowsTheWalk) {
  SimConfig c = SimConfig::from_preset("lab");
  c.frames = 2;
  c.arm_preset = "inchworm7";
  c.walk = SimWalk{0.0, 2.0, 2, {0.0, 0.75, 0.0, -6.0, 0.0}};
  const TunnelSimulator sim(c);
  for (int i : {0, 1}) {
    const SimArmState s = *sim.arm_state(i);
    EXPECT_NEAR(s.base.translation().x(), 2.0 * i - c.arm_setback_m, 1e-12);
    EXPECT_LT(s.ik_error_m, 1e-4);
    EXPECT_NEAR(sim.pose(i).translation().x(), 2.0 * i, 0.01);
  }
}

TEST(SimWalkTest, LayoutValidationAndJsonRoundTrip) {
  SimConfig c = sectioned_config();
  c.frames = 6;
  c.diaphragm_x_m = {2.2};
  c.walk = SimWalk{0.0, 2.0, 3, {0.05, 0.6, 1.0, -2.0, 3.0}};
  c.sections_start_x_m = 0.25;
  const nlohmann::json j = sim_config_to_json(c);
  ASSERT_TRUE(j.contains("sections"));
  EXPECT_EQ(j.at("sections").size(), 3u);
  const SimConfig back = sim_config_from_json(j, "test");
  EXPECT_EQ(sim_config_to_json(back), j);
  EXPECT_EQ(back.sections[1].width_m, 0.80);
  EXPECT_EQ(back.sections_start_x_m, 0.25);
  EXPECT_EQ(back.walk->stops, 3);
  EXPECT_EQ(back.walk->pose.yaw_deg, 3.0);
  EXPECT_EQ(back.diaphragm_x_m, std::vector<double>{2.2});
  nlohmann::json bad = j;
  bad["sections"][0]["length_m"] = 0.0;
  EXPECT_THROW(sim_config_from_json(bad, "x.json"), InputError);
  bad = j;
  bad["walk"] = 3;
  EXPECT_THROW(sim_config_from_json(bad, "x.json"), InputError);

  auto fails = [](SimConfig x, const std::string& needle) {
    try {
      x.validate();
    } catch (const ParameterError& e) {
      return std::string(e.what()).find(needle) != std::string::npos;
    }
    return false;
  };
  SimConfig x = c;
  x.sections[1].length_m = 0.0;
  EXPECT_TRUE(fails(x, "sections[1].length_m"));
  x = c;
  x.sections[2].width_m = 6.0;
  EXPECT_TRUE(fails(x, "sections[2].width_m"));
  x = c;
  x.walk->stops = 0;
  EXPECT_TRUE(fails(x, "walk stops"));
  x = c;
  x.frames = 2;
  EXPECT_TRUE(fails(x, "fewer than the walk's 3 stops"));
  x = c;
  x.sections[1].width_m = 0.45;  // the manhole opening (0.45 m) must fit every section
  EXPECT_TRUE(fails(x, "manhole_width_m"));
  x = c;
  x.walk->pose.z_rel = 0.99;  // into the roof plate of the lowest section
  EXPECT_TRUE(fails(x, "walk pose z_rel"));
  x = c;
  x.diaphragm_x_m = {std::nan("")};
  EXPECT_TRUE(fails(x, "diaphragm_x_m"));
  x = c;
  x.poses.clear();  // a walk does not need the pose groups
  EXPECT_NO_THROW(x.validate());
}

TEST(SimWalkTest, GroundTruthListsSectionsAndDiaphragms) {
  const fs::path dir = fresh_dir("sections");
  SimConfig c = sectioned_config();
  c.frames = 2;
  c.diaphragm_x_m = {2.0};
  c.distance_to_manhole_m = 4.0;  // manhole plate at x = 4
  c.walk = SimWalk{0.5, 2.5, 2, {0.0, 0.5, 0.0, 0.0, 0.0}};
  write_sim_dataset(dir.string(), c);
  std::ifstream in(dir / "dataset.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& gt = j.at("ground_truth");
  EXPECT_EQ(gt.at("width_m").get<double>(), 0.84);  // the section at the first camera
  EXPECT_EQ(gt.at("height_m").get<double>(), 1.30);
  EXPECT_EQ(gt.at("manhole_x_m").get<double>(), 4.0);
  EXPECT_EQ(gt.at("diaphragms_x_m"), nlohmann::json::array({2.0, 4.0}));
  // Cameras at 0.5 and 2.5: the extent is 0.5 - 6 .. 2.5 + 6 m.
  const nlohmann::json& sec = gt.at("sections");
  ASSERT_EQ(sec.size(), 3u);
  const double expect[3][4] = {
      {-5.5, 1.5, 0.84, 1.30}, {1.5, 3.0, 0.80, 1.28}, {3.0, 8.5, 0.82, 1.32}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(sec[k].at("from_x_m").get<double>(), expect[k][0], 1e-12) << k;
    EXPECT_NEAR(sec[k].at("to_x_m").get<double>(), expect[k][1], 1e-12) << k;
    EXPECT_EQ(sec[k].at("width_m").get<double>(), expect[k][2]) << k;
    EXPECT_EQ(sec[k].at("height_m").get<double>(), expect[k][3]) << k;
  }
  std::map<std::string, nlohmann::json> by_name;
  for (const nlohmann::json& s : gt.at("surfaces")) by_name[s.at("name")] = s;
  EXPECT_EQ(by_name.at("section1/left/middle").at("section"), 1);
  EXPECT_EQ(by_name.at("section1/left/middle").at("id"), 22);
  EXPECT_EQ(by_name.at("joint/0").at("wall"), "joint");
  EXPECT_EQ(by_name.at("joint/0").at("id"), 61);
  EXPECT_EQ(by_name.at("manhole").at("id"), 63);
  EXPECT_EQ(by_name.at("diaphragm/0").at("id"), 64);
  EXPECT_NEAR(by_name.at("diaphragm/0").at("offset_m").get<double>(), 2.0, 1e-12);
  // Frames: one pose group per station, the plate's distance from each.
  ASSERT_EQ(j.at("frames").size(), 2u);
  EXPECT_EQ(j.at("frames")[1].at("pose_group"), 1);
  EXPECT_NEAR(j.at("frames")[0].at("distance_to_manhole_m").get<double>(), 3.5, 1e-12);
  EXPECT_NEAR(j.at("frames")[1].at("pose")[3].get<double>(), 2.5, 1e-12);
  // The simulator section regenerates the same layout.
  const SimConfig back = sim_config_from_json(j.at("simulator"), "dataset.json");
  EXPECT_EQ(back.sections.size(), 3u);
  EXPECT_EQ(back.walk->end_x_m, 2.5);
  fs::remove_all(dir);
}

TEST(SimWalkTest, SpecParsersReadTheFlagFormats) {
  const std::vector<SimSection> s = parse_sim_sections("--sections", "1.5:0.84x1.30, 2:0.80X1.28");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].length_m, 1.5);
  EXPECT_EQ(s[0].width_m, 0.84);
  EXPECT_EQ(s[1].height_m, 1.28);
  EXPECT_EQ(parse_sim_numbers("--diaphragms", "2,-1.5,3e1"),
            (std::vector<double>{2.0, -1.5, 30.0}));
  const SimWalk w = parse_sim_walk("--walk", "0,4.5,7");
  EXPECT_EQ(w.end_x_m, 4.5);
  EXPECT_EQ(w.stops, 7);
  for (const char* bad :
       {"", "1.5", "1.5:0.84", "1.5:0.84x", "a:0.84x1.3", "1.5:0.84x1.3,", "-1:0.8x1.2"})
    EXPECT_THROW(parse_sim_sections("--sections", bad), ParameterError) << bad;
  EXPECT_THROW(parse_sim_numbers("--diaphragms", "1,,2"), ParameterError);
  EXPECT_THROW(parse_sim_numbers("--diaphragms", "1,inf"), ParameterError);
  EXPECT_THROW(parse_sim_walk("--walk", "0,1"), ParameterError);
  EXPECT_THROW(parse_sim_walk("--walk", "0,1,2.5"), ParameterError);
  EXPECT_THROW(parse_sim_walk("--walk", "0,1,0"), ParameterError);
}

// Runs the CLI; returns its exit status and its stderr.
int run_cli_err(const std::string& args, std::string& err) {
  const fs::path err_file = fresh_dir("stderr");
  const int status = std::system((std::string(TUNNELMAP_CLI_PATH) + " " + args + " >/dev/null 2>" +
                                  err_file.string()).c_str());
  std::ifstream in(err_file);
  err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  fs::remove(err_file);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SimWalkTest, CliSectionsDiaphragmsAndWalk) {
  const fs::path dir = fresh_dir("cli_walk");
  EXPECT_EQ(run_cli("simulate " + dir.string() +
                    " --frames 2 --sections 1.5:0.84x1.30,1.5:0.80x1.28,2:0.82x1.32"
                    " --sections-start 0.5"
                    " --diaphragms 4.5 --walk 0.2,1,2 --walk-pose 0.05,0.9,-2 --seed 3 --quiet"),
            0);
  std::ifstream in(dir / "dataset.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& sim = j.at("simulator");
  EXPECT_EQ(sim.at("sections").size(), 3u);
  EXPECT_EQ(sim.at("sections")[1].at("width_m").get<double>(), 0.80);
  EXPECT_EQ(sim.at("sections_start_x_m").get<double>(), 0.5);
  EXPECT_EQ(sim.at("diaphragm_x_m"), nlohmann::json::array({4.5}));
  EXPECT_EQ(sim.at("walk").at("stops"), 2);
  EXPECT_EQ(sim.at("walk").at("pose").at("z_rel").get<double>(), 0.9);
  EXPECT_EQ(sim.at("walk").at("pose").at("pitch_deg").get<double>(), -2.0);
  EXPECT_EQ(j.at("ground_truth").at("diaphragms_x_m"), nlohmann::json::array({4.5}));
  EXPECT_EQ(j.at("ground_truth").at("sections").size(), 3u);
  EXPECT_TRUE(fs::is_regular_file(dir / "depth/000001.png"));
  fs::remove_all(dir);

  // Malformed values: exit 2, one line naming the flag, nothing written.
  const std::pair<const char*, const char*> bad[] = {
      {"--sections 1.5:0.84", "--sections"},
      {"--sections 1.5:0.84xwide", "--sections"},
      {"--sections 0:0.84x1.3", "--sections"},
      {"--sections 1:9x1.3", "--sections"},
      {"--sections 1:0.84x1.3 --width 0.9", "--sections"},
      {"--sections-start 1", "--sections-start"},
      {"--diaphragms 2,x", "--diaphragms"},
      {"--walk 0,1", "--walk"},
      {"--walk 0,1,2.5", "--walk"},
      {"--walk 0,1,50 --frames 3", "--walk"},
      {"--walk-pose 0,0.5,0", "--walk-pose"},
      {"--walk 0,1,2 --walk-pose 0,2,0", "--walk-pose"},
      {"--walk 0,1,2 --walk-pose 0,0.5", "--walk-pose"},
  };
  for (const auto& [args, flag] : bad) {
    std::string err;
    EXPECT_EQ(run_cli_err("simulate " + dir.string() + " " + args, err), 2) << args;
    EXPECT_NE(err.find(flag), std::string::npos) << args << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << args << ": " << err;
  }
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace tunnelmap
