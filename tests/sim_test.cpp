// Tests of the simulated tunnel depth camera (core/sim) and its dataset writer.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <cstdio>
#include <sys/wait.h>

#include "core/io/dataset.h"
#include "core/sim/sensor_model.h"
#include "core/sim/sim_config_json.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/sim/tunnel_simulator.h"
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
  EXPECT_THROW(write_sim_dataset(foreign.string(), c), InputError);
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

}  // namespace
}  // namespace tunnelmap
