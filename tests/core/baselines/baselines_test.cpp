// The paper's two comparison methods (core/baselines): R&L (RANSAC + least squares, then the
// PG&C template fit) and Qhull (convex hull + axial alignment), on exact ray-cast box tunnels.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/baselines/method.h"
#include "core/baselines/method_runner.h"
#include "core/baselines/qhull_tunnel.h"
#include "core/baselines/ransac_lse.h"
#include "core/normals/cloud_builder.h"
#include "core/tunnel/tunnel_detector.h"
#include "core/util/error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/synthetic_scene.h"

namespace tunnelmap {
namespace {

constexpr double kW = 0.82, kH = 1.30;

// A long box tunnel along +X (y across, z up), closed far away, camera inside looking along it.
test::SyntheticFrame tunnel_frame(double yaw_deg, double noise_m, double cam_y = 0.1, double cam_z = 0.7) {
  const auto planes = test::box_room({-1.0, -kW / 2, 0.0}, {4.0, kW / 2, kH});
  const double yaw = yaw_deg * M_PI / 180.0;
  const Eigen::Vector3d eye(0.0, cam_y, cam_z);
  const Eigen::Vector3d target = eye + Eigen::Vector3d(std::cos(yaw), std::sin(yaw), -0.1);
  test::SyntheticFrame f = test::render_planes(planes, test::look_at(eye, target),
                                               {-1.0, -kW / 2, 0.0}, {4.0, kW / 2, kH}, noise_m, 3);
  f.frame.pose = test::look_at(eye, target);
  return f;
}

OrganizedCloud cloud_of(const DepthFrame& frame) {
  OrganizedCloud cloud;
  CloudOptions o;
  o.max_range_m = 5.0;
  build_cloud(frame, o, cloud);
  return cloud;
}

Eigen::Vector3d camera_up(const DepthFrame& f) { return f.pose->linear().transpose() * Eigen::Vector3d::UnitZ(); }

RansacLseOptions quick_ransac() {
  RansacLseOptions o;
  o.iterations = 5;
  o.sample_step = 4;
  return o;
}

TEST(MethodNames, ParseAndName) {
  EXPECT_EQ(parse_method("pgc"), Method::Pgc);
  EXPECT_EQ(parse_method("ransac"), Method::Ransac);
  EXPECT_EQ(parse_method("qhull"), Method::Qhull);
  EXPECT_STREQ(method_name(Method::Ransac), "ransac");
  EXPECT_STREQ(method_display_name(Method::Qhull), "Qhull");
  EXPECT_THROW(parse_method("hough"), ParameterError);
  const auto list = parse_methods("qhull,pgc");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], Method::Qhull);
  EXPECT_THROW(parse_methods(""), ParameterError);
}

TEST(RansacLse, FindsTheTunnelWallsAndTheTemplateFitMeasuresThem) {
  const auto f = tunnel_frame(5.0, 0.0);
  const OrganizedCloud cloud = cloud_of(f.frame);
  const RansacLseResult r = ransac_lse_planes(cloud, quick_ransac());
  ASSERT_GE(r.planes.planes.size(), 4u);
  for (const PlaneSegment& p : r.planes.planes) {
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-9);
    EXPECT_LT(p.normal.dot(p.centroid), 0.0) << "normals face the camera like PG&C's";
    EXPECT_LT(p.rms_m, 0.002) << "noise-free walls fit exactly";
    EXPECT_EQ(p.points % 16, 0) << "points count the pixels covered (step 4 -> 16 each)";
  }
  const TunnelMap map = detect_tunnel(r.planes, camera_up(f.frame), TunnelOptions(), nullptr);
  ASSERT_TRUE(map.detected) << map.status << ": " << map.reason;
  EXPECT_NEAR(map.width_m, kW, 0.003);
  EXPECT_NEAR(map.height_m, kH, 0.003);
}

TEST(RansacLse, IsReproducibleAndMoreIterationsNeverIncreaseTheError) {
  const auto f = tunnel_frame(-8.0, 0.004);
  const OrganizedCloud cloud = cloud_of(f.frame);
  RansacLseOptions one = quick_ransac();
  one.iterations = 1;
  RansacLseOptions many = quick_ransac();
  many.iterations = 8;
  const RansacLseResult a = ransac_lse_planes(cloud, many), b = ransac_lse_planes(cloud, many);
  EXPECT_DOUBLE_EQ(a.squared_error, b.squared_error);
  EXPECT_EQ(a.winning_iteration, b.winning_iteration);
  EXPECT_EQ(a.planes.labels, b.planes.labels);
  // Iteration 0 of `many` is the single run of `one`: the minimum can only be lower.
  EXPECT_LE(a.squared_error, ransac_lse_planes(cloud, one).squared_error);
}

TEST(RansacLse, LabelsOnlyTheSampledPixels) {
  const auto f = tunnel_frame(0.0, 0.0);
  const RansacLseResult r = ransac_lse_planes(cloud_of(f.frame), quick_ransac());
  for (int v = 0; v < r.planes.height; ++v)
    for (int u = 0; u < r.planes.width; ++u)
      if (u % 4 || v % 4) {
        ASSERT_EQ(r.planes.labels[v * r.planes.width + u], 0) << u << "," << v;
      }
}

TEST(RansacLse, RejectsBadOptions) {
  const OrganizedCloud cloud = cloud_of(tunnel_frame(0, 0).frame);
  RansacLseOptions o;
  o.iterations = 0;
  EXPECT_THROW(ransac_lse_planes(cloud, o), ParameterError);
  o = RansacLseOptions();
  o.distance_m = 0;
  EXPECT_THROW(ransac_lse_planes(cloud, o), ParameterError);
}

TEST(QhullTunnel, MeasuresANoiseFreeBoxTunnelFromAYawedCamera) {
  for (double yaw : {0.0, 12.0, -20.0}) {
    const auto f = tunnel_frame(yaw, 0.0);
    const QhullTunnelResult r = qhull_tunnel(cloud_of(f.frame), camera_up(f.frame), TunnelOptions(), nullptr);
    ASSERT_TRUE(r.map.detected) << r.map.status << ": " << r.map.reason;
    EXPECT_NEAR(r.map.width_m, kW, 0.004) << "yaw " << yaw;
    EXPECT_NEAR(r.map.height_m, kH, 0.004) << "yaw " << yaw;
    EXPECT_GT(r.hull_vertices, 8);
    // The axis found is the tunnel's (+X world) seen from the camera.
    const Eigen::Vector3d axis_world = f.frame.pose->linear() * r.map.axis_dir;
    EXPECT_GT(std::abs(axis_world.x()), std::cos(0.5 * M_PI / 180.0)) << "yaw " << yaw;
  }
}

TEST(QhullTunnel, NoiseOnlyWidensTheHull) {
  // The hull takes the extreme points: noise can only push the measured size outward.
  const auto f = tunnel_frame(6.0, 0.01);
  const QhullTunnelResult r = qhull_tunnel(cloud_of(f.frame), camera_up(f.frame), TunnelOptions(), nullptr);
  ASSERT_TRUE(r.map.detected) << r.map.reason;
  EXPECT_GT(r.map.width_m, kW + 0.003);
  EXPECT_GT(r.map.height_m, kH + 0.003);
}

TEST(QhullTunnel, TooFewPointsAndTemplateWindowAreReported) {
  const auto f = tunnel_frame(0.0, 0.0);
  OrganizedCloud cloud = cloud_of(f.frame);
  QhullOptions o;
  o.min_points = static_cast<int>(cloud.points.size()) + 1;
  EXPECT_EQ(qhull_tunnel(cloud, camera_up(f.frame), TunnelOptions(), nullptr, o).map.status, TunnelStatus::TooFewPoints);
  TunnelOptions narrow;
  narrow.width_max_m = 0.5;
  const QhullTunnelResult r = qhull_tunnel(cloud, camera_up(f.frame), narrow, nullptr);
  EXPECT_FALSE(r.map.detected);
  EXPECT_EQ(r.map.status, TunnelStatus::OutOfTemplate);
  EXPECT_THROW(qhull_tunnel(cloud, Eigen::Vector3d::Zero(), TunnelOptions(), nullptr), ParameterError);
}

TEST(MethodRunner, RunsEachMethodWithTheSameOutputs) {
  const auto f = tunnel_frame(4.0, 0.0);
  BaselineOptions b;
  b.ransac = quick_ransac();
  for (Method m : {Method::Pgc, Method::Ransac, Method::Qhull}) {
    MethodRunner runner(m, Parameters(), b);
    TunnelContext context;
    FrameResult r;
    runner.run(f.frame, r, &context);
    ASSERT_TRUE(r.map.detected) << method_name(m) << ": " << r.map.reason;
    EXPECT_NEAR(r.map.width_m, kW, 0.005) << method_name(m);
    EXPECT_NEAR(r.map.height_m, kH, 0.005) << method_name(m);
    EXPECT_FALSE(context.empty()) << "a detected map is accepted into the context";
    for (const char* k : {"cloud", "normals", "planes", "tunnel", "total"}) EXPECT_EQ(r.timings_ms.count(k), 1u) << k;
    EXPECT_EQ(r.planes.planes.empty(), m == Method::Qhull) << "Qhull produces no planes";
  }
}

TEST(DetectCli, MethodOptionSelectsTheBaselineAndIsRecordedInTheJson) {
  testing::IoTempDir tmp;
  ASSERT_EQ(testing::run_cli("simulate " + tmp.file("ds") + " --preset lab --frames 1").exit_code, 0);
  const auto run = testing::run_cli("detect " + tmp.file("ds") + " --method qhull --json " + tmp.file("r.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto doc = nlohmann::json::parse(testing::slurp(tmp.file("r.json")));
  EXPECT_EQ(doc["method"], "qhull");
  EXPECT_EQ(doc["frames"][0]["planes"], 0) << "Qhull produces no planes";
  const auto bad = testing::run_cli("detect " + tmp.file("ds") + " --method hough");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("unknown method 'hough'"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace tunnelmap
