// The Table 1 evaluation (core/evaluation): segmentation metrics, report writers, sweeps, the
// symmetric zone prior, and the reduced CI protocol asserting the acceptance bounds
// (core/evaluation/table1_bounds.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "core/evaluation/protocol.h"
#include "core/planes/grow_options.h"
#include "core/evaluation/report_csv.h"
#include "core/evaluation/report_markdown.h"
#include "core/evaluation/report_plot.h"
#include "core/evaluation/segmentation_metrics.h"
#include "core/evaluation/sweeps.h"
#include "core/evaluation/table1_bounds.h"
#include "core/sim/tunnel_simulator.h"
#include "core/tunnel/zone_clustering.h"
#include "core/util/error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;

TEST(SegmentationMetrics, CountsCorrectPlanesAndFoundSurfaces) {
  // 10x10 image: surface 1 = left half, surface 2 = right half, 65535 (rivet) = last row.
  PlaneSegments p;
  p.width = p.height = 10;
  p.labels.assign(100, 0);
  std::vector<std::uint16_t> truth(100);
  for (int v = 0; v < 10; ++v)
    for (int u = 0; u < 10; ++u) truth[v * 10 + u] = v == 9 ? 65535 : (u < 5 ? 1 : 2);
  // Plane 1: 20 pixels inside surface 1 -> correct. Plane 2: straddles 1 and 2 (50/50) -> wrong.
  // Plane 3: mostly rivet -> wrong.
  for (int v = 0; v < 4; ++v)
    for (int u = 0; u < 5; ++u) p.labels[v * 10 + u] = 1;
  for (int u = 3; u < 7; ++u) p.labels[5 * 10 + u] = 2;
  for (int u = 0; u < 10; ++u) p.labels[9 * 10 + u] = 3;
  for (int id = 1; id <= 3; ++id) {
    PlaneSegment s;
    s.id = id;
    p.planes.push_back(s);
  }
  SegmentationOptions o;
  o.min_surface_pixels = 10;
  const SegmentationScore s = score_segmentation(p, truth, o);
  EXPECT_EQ(s.planes, 3);
  EXPECT_EQ(s.correct_planes, 1);
  EXPECT_EQ(s.surfaces, 2);  // the rivet is never a surface
  EXPECT_EQ(s.found_surfaces, 1);
  EXPECT_NEAR(s.precision(), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.recall(), 0.5, 1e-12);
  // 80 % rule: 4 of 5 pixels on one surface is still correct.
  p.labels[4 * 10 + 5] = 1;  // plane 1 now 20 on surface 1 + 1 on surface 2 -> 95 %
  EXPECT_EQ(score_segmentation(p, truth, o).correct_planes, 1);
  truth.pop_back();
  EXPECT_THROW(score_segmentation(p, truth, o), InputError);
}

// The physical-size criterion of docs/recall.md. A scene rendered by ray casting: each square (centre,
// in-plane axes a and b, half side) is a true surface; pixels whose ray hits a square get its
// id and the exact 3-D point; every other pixel sees nothing (NaN point).
struct TrueSquare {
  Eigen::Vector3d centre, a, b;
  double half_side_m;
};

struct SquareScene {
  OrganizedCloud cloud;
  std::vector<std::uint16_t> truth;
  PlaneSegments planes;  // no planes detected yet: labels all 0
};

SquareScene render_squares(const Intrinsics& K, const std::vector<TrueSquare>& squares) {
  SquareScene s;
  s.cloud.width = s.planes.width = K.width;
  s.cloud.height = s.planes.height = K.height;
  s.cloud.intrinsics = K;
  const std::size_t n = static_cast<std::size_t>(K.width) * K.height;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  s.cloud.points.assign(n, Eigen::Vector3f(nan, nan, nan));
  s.cloud.normals.assign(n, Eigen::Vector3f(nan, nan, nan));
  s.truth.assign(n, 0);
  s.planes.labels.assign(n, 0);
  for (int v = 0; v < K.height; ++v)
    for (int u = 0; u < K.width; ++u) {
      const Eigen::Vector3d r = K.ray(u, v);
      for (std::size_t k = 0; k < squares.size(); ++k) {
        const TrueSquare& q = squares[k];
        const Eigen::Vector3d normal = q.a.cross(q.b).normalized();
        const double t = normal.dot(q.centre) / normal.dot(r);
        const Eigen::Vector3d x = t * r - q.centre;
        if (t <= 0 || std::abs(x.dot(q.a)) > q.half_side_m || std::abs(x.dot(q.b)) > q.half_side_m) continue;
        s.cloud.points[s.cloud.index(u, v)] = (t * r).cast<float>();
        s.truth[s.cloud.index(u, v)] = static_cast<std::uint16_t>(k + 1);
        break;
      }
    }
  return s;
}

Intrinsics small_camera(double f, int size) {
  Intrinsics K;
  K.fx = K.fy = f;
  K.cx = K.cy = (size - 1) / 2.0;
  K.width = K.height = size;
  return K;
}

TEST(SegmentationMetrics, VisibleAreaOfFrontoParallelAndTiltedSquares) {
  // 0.40 m square facing the camera at 2 m (100 x 100 px of (2/500)^2 m^2 each = 0.16 m^2) and
  // a 0.50 m square at 2 m turned 60 degrees about the vertical (0.25 m^2 seen obliquely).
  const double c60 = std::cos(M_PI / 3), s60 = std::sin(M_PI / 3);
  const SquareScene s = render_squares(
      small_camera(500, 400), {{{-0.3, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.20},
                               {{0.3, 0, 2.0}, {c60, 0, s60}, Eigen::Vector3d::UnitY(), 0.25}});
  std::vector<SurfaceDetail> d;
  const SegmentationScore score =
      score_segmentation(s.planes, s.truth, s.cloud, SegmentationOptions::by_size(40, 0.004), &d);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(score.surfaces, 2);
  EXPECT_EQ(score.found_surfaces, 0);  // no plane detected
  EXPECT_NEAR(d[0].area_m2, 0.16, 0.02 * 0.16);
  EXPECT_NEAR(d[0].mean_depth_m, 2.0, 1e-6);
  EXPECT_NEAR(d[0].normal.z(), -1.0, 1e-6);  // facing the camera
  EXPECT_NEAR(d[1].area_m2, 0.25, 0.02 * 0.25);
  // Turned 60 degrees away from the optical axis, seen along a ray 8.5 degrees the other way.
  EXPECT_NEAR(d[1].incidence_deg, 68.5, 3.0);
  // Foreshortened to about cos(68.5 deg) of the 15625 px it would cover facing the camera.
  EXPECT_NEAR(d[1].pixels, 0.37 * 15625, 0.1 * 0.37 * 15625);
  EXPECT_EQ(d[0].pixels, d[0].truth_pixels);
}

TEST(SegmentationMetrics, SurfacesBelowTheMinimumAreaOrPointsAreNotCounted) {
  // At 2 m with f = 500 a pixel covers 1.6e-5 m^2: a 0.048 m square (0.0023 m^2, 144 px) is
  // below 0.004 m^2; a 0.08 m square (0.0064 m^2, 400 px) is above.
  const SquareScene s = render_squares(
      small_camera(500, 200), {{{-0.2, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.024},
                               {{0.2, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.04}});
  std::vector<SurfaceDetail> d;
  const SegmentationOptions o = SegmentationOptions::by_size(40, 0.004);
  EXPECT_EQ(score_segmentation(s.planes, s.truth, s.cloud, o, &d).surfaces, 1);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_FALSE(d[0].counted);
  EXPECT_EQ(d[0].pixels, 144);
  EXPECT_NEAR(d[0].area_m2, 0.002304, 0.02 * 0.002304);
  EXPECT_TRUE(d[1].counted);
  EXPECT_NEAR(d[1].area_m2, 0.0064, 0.02 * 0.0064);
  // Wide-angle camera (f = 100, 4e-4 m^2 a pixel): a 0.12 m square is 0.0144 m^2 but only
  // 36 px, fewer than the 40 points PG&C needs.
  const SquareScene wide = render_squares(
      small_camera(100, 100), {{{0, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.06}});
  EXPECT_EQ(score_segmentation(wide.planes, wide.truth, wide.cloud, o, &d).surfaces, 0);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].pixels, 36);
  EXPECT_NEAR(d[0].area_m2, 0.0144, 1e-6);
}

TEST(SegmentationMetrics, MajorityOverlapAndPerSurfaceDetail) {
  // Two 0.4 m squares side by side at 2 m (100 x 100 px each, touching at u = 100).
  SquareScene s = render_squares(
      small_camera(500, 200), {{{-0.2, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.2},
                               {{0.2, 0, 2.0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0.2}});
  const auto id_at = [&](int u, int v) { return s.truth[s.cloud.index(u, v)]; };
  ASSERT_EQ(id_at(99, 100), 1);
  ASSERT_EQ(id_at(100, 100), 2);
  // Plane 1: a 20-column band over both squares, 10 columns on each: exactly 50 %, wrong.
  // Plane 2: 60 columns on square 2 and 40 on square 1: 60 %, correct for square 2.
  for (int v = 50; v < 100; ++v)
    for (int u = 90; u < 110; ++u) s.planes.labels[s.cloud.index(u, v)] = 1;
  for (int v = 110; v < 140; ++v)
    for (int u = 60; u < 160; ++u) s.planes.labels[s.cloud.index(u, v)] = 2;
  s.planes.planes.resize(2);
  s.planes.planes[0].id = 1, s.planes.planes[1].id = 2;
  // Square 1 loses a quarter of its pixels to dropout: they count in truth_pixels only.
  for (int v = 50; v < 75; ++v)
    for (int u = 0; u < 100; ++u)
      if (id_at(u, v) == 1) s.cloud.points[s.cloud.index(u, v)].setConstant(std::numeric_limits<float>::quiet_NaN());
  std::vector<SurfaceDetail> d;
  const SegmentationScore score =
      score_segmentation(s.planes, s.truth, s.cloud, SegmentationOptions::by_size(40, 0.004), &d);
  EXPECT_EQ(score.planes, 2);
  EXPECT_EQ(score.correct_planes, 1);
  EXPECT_EQ(score.surfaces, 2);
  EXPECT_EQ(score.found_surfaces, 1);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_FALSE(d[0].found);
  EXPECT_EQ(d[0].truth_pixels, 10000);
  EXPECT_EQ(d[0].pixels, 7500);
  EXPECT_NEAR(d[0].area_m2, 0.12, 0.02 * 0.12);
  EXPECT_EQ(d[0].best_plane, 2);  // 30 x 40 px of plane 2 beat plane 1's 50 x 10
  EXPECT_EQ(d[0].best_plane_pixels, 1200);
  EXPECT_NEAR(d[0].best_plane_share, 0.4, 1e-12);
  EXPECT_TRUE(d[1].found);
  EXPECT_EQ(d[1].best_plane, 2);
  EXPECT_NEAR(d[1].best_plane_share, 0.6, 1e-12);
  EXPECT_EQ(d[1].labelled_pixels, 500 + 1800);
  // The legacy pixel rule still works on the same frame: neither square has 20000 px.
  SegmentationOptions legacy;
  legacy.min_surface_pixels = 20000;
  EXPECT_EQ(score_segmentation(s.planes, s.truth, legacy).surfaces, 0);
  s.truth.pop_back();
  EXPECT_THROW(score_segmentation(s.planes, s.truth, s.cloud), InputError);
}

TEST(ZonePrior, WallSeenOnlyByItsMiddlePlateBorrowsTheEdgeStep) {
  // Opposite wall: edge band at 0.420 (900 px) outside the middle plate at 0.412 (50000 px).
  const std::vector<ZoneCluster> opposite{{0.420, 2, 900}, {0.412, 1, 50000}};
  EXPECT_NEAR(observed_edge_step(opposite, 300, 0.03), 0.008, 1e-12);
  EXPECT_TRUE(single_supported_zone({{0.180, 1, 47000}, {0.19, 1, 200}}, 300));
  EXPECT_FALSE(single_supported_zone(opposite, 300));
  // No step when the outermost cluster is the largest, or the step is implausibly large.
  EXPECT_EQ(observed_edge_step({{0.420, 1, 60000}, {0.412, 1, 500}}, 300, 0.03), 0.0);
  EXPECT_EQ(observed_edge_step({{0.480, 1, 900}, {0.412, 1, 50000}}, 300, 0.03), 0.0);
}

std::vector<CellResult> fake_results() {
  std::vector<CellResult> rs;
  for (Method m : {Method::Pgc, Method::Qhull, Method::Ransac}) {
    CellResult r;
    r.experiment = "lab";
    r.cell = "Pose 1";
    r.method = m;
    r.gt_width_m = 0.82;
    r.gt_height_m = 1.30;
    r.frames = 10;
    r.detected = m == Method::Qhull ? 9 : 10;
    r.width_mean_m = m == Method::Ransac ? 0.805 : 0.8195;
    r.width_std_m = 0.001;
    r.height_mean_m = m == Method::Qhull ? 1.34 : 1.2995;
    r.height_std_m = 0.002;
    r.width_abs_error_m = std::abs(r.width_mean_m - 0.82);
    r.height_abs_error_m = std::abs(r.height_mean_m - 1.30);
    r.ms_mean = m == Method::Ransac ? 4000 : 40;
    r.has_segmentation = m != Method::Qhull;
    r.segmentation.planes = 100;
    r.segmentation.correct_planes = 90;
    r.segmentation.surfaces = 10;
    r.segmentation.found_surfaces = 8;
    rs.push_back(r);
  }
  return rs;
}

TEST(EvaluationReports, MarkdownCsvAndPngCarryTheNumbers) {
  const auto rs = fake_results();
  const auto bounds = check_table1_bounds(rs);
  const std::string md = evaluation_markdown(rs, bounds, ReportInfo());
  EXPECT_NE(md.find("| Pose 1 | 820 (1.0) | 1300 (2.0) | 820 (1.0) | 1340 (2.0) | 805 (1.0) | 1300 (2.0) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("9/10"), std::string::npos);
  EXPECT_NE(md.find("| 100.0 |"), std::string::npos) << "R&L is 100x slower in the speed table\n" << md;
  const std::string csv = evaluation_csv(rs);
  EXPECT_EQ(testing::count_lines(csv), 4);
  EXPECT_NE(csv.find("lab,Pose 1,0,qhull,10,9,0.9000,820.0,1300.0,819.50,1.00,1340.00,2.00,0.50,40.00,40.00"),
            std::string::npos)
      << csv;
  IoTempDir tmp;
  write_table1_plot(tmp.file("t.png"), rs);
  const cv::Mat img = cv::imread(tmp.file("t.png"));
  EXPECT_EQ(img.cols, 1100);
  EXPECT_GT(img.rows, 300);
  EXPECT_THROW(write_table1_plot(tmp.file("missing/t.png"), rs), InputError);
}

TEST(EvaluationBounds, PassAndFailAsSpecified) {
  auto rs = fake_results();
  auto b = check_table1_bounds(rs);
  EXPECT_TRUE(std::all_of(b.begin(), b.end(), [](const BoundCheck& c) { return c.pass; }));
  rs[0].width_std_m = 0.0035;  // lab sigma bound is 3 mm
  rs[2].ms_mean = 1000;        // only 25x slower
  b = check_table1_bounds(rs);
  EXPECT_EQ(std::count_if(b.begin(), b.end(), [](const BoundCheck& c) { return !c.pass; }), 2);
  EXPECT_EQ(check_table1_bounds(rs, false).size() + 1, b.size()) << "speed check left out";
}

TEST(Sweeps, ApplyValuesAndRejectUnknownNames) {
  SimConfig c = SimConfig::from_preset("field");
  apply_sweep_value("distance_to_manhole_m", 1.2, c);
  EXPECT_EQ(c.distance_to_manhole_m, 1.2);
  EXPECT_TRUE(c.manhole_distances_m.empty());
  apply_sweep_value("plate_thickness_mm", 12, c);
  EXPECT_DOUBLE_EQ(c.plate_thickness_m[2], 0.012);
  EXPECT_THROW(apply_sweep_value("gravity", 1, c), ParameterError);
  EXPECT_EQ(default_sweeps().size(), 6u);
  EXPECT_THROW(default_sweeps({"gravity"}), ParameterError);
}

TEST(Sweeps, OneSweepValueRunsAllMethodsOnPooledPoses) {
  ProtocolOptions o;
  o.frames_per_cell = 1;
  o.ransac_frames_per_cell = 1;
  o.baselines.ransac.sample_step = 8;
  o.baselines.ransac.iterations = 10;
  const auto rs = run_sweeps({{"noise_scale", "lab", {2.0}}}, o);
  ASSERT_EQ(rs.size(), 3u);
  for (const CellResult& r : rs) {
    EXPECT_EQ(r.experiment, "noise_scale");
    EXPECT_EQ(r.cell, "noise_scale=2");
    EXPECT_EQ(r.frames, 3) << "one frame for each of the lab's 3 poses";
  }
}

// The reduced protocol CI runs (docs/evaluation.md): 3 frames per cell for PG&C and Qhull, 1 per
// cell for R&L on every 8th pixel (its 100 iterations are slow by design). Asserts the acceptance
// bounds for PG&C and the paper's qualitative findings.
TEST(Table1Protocol, ReducedProtocolMeetsTheBounds) {
  ProtocolOptions o;
  o.frames_per_cell = 3;
  o.ransac_frames_per_cell = 1;
  o.baselines.ransac.sample_step = 8;
  const auto rs = run_table1(o);
  ASSERT_EQ(rs.size(), 18u);
  for (const BoundCheck& b : check_table1_bounds(rs, false))
    EXPECT_TRUE(b.pass) << b.name << ": measured " << b.value << ", limit " << b.limit;
  for (const CellResult& r : rs) {
    if (r.method == Method::Ransac) {  // the paper: R&L constantly underestimates
      ASSERT_EQ(r.detected, 1) << r.cell;
      EXPECT_LT(r.width_mean_m, *r.gt_width_m - 0.005) << r.cell;
      EXPECT_LT(r.height_mean_m, *r.gt_height_m) << r.cell;
    }
    if (r.method == Method::Pgc) {
      ASSERT_TRUE(r.has_segmentation);
      // Lowest cell: 5 m to the plate, where far planes of < 100 px straddle plates 6-12 mm
      // apart. Measured there: 0.49 with the defaults (grid step 2 and its edge-on pass, which
      // adds far edge-on planes: 0.51 without it), 0.61 with every-pixel growing. By the
      // majority rule of docs/recall.md precision is >= 98.9 %.
      EXPECT_GT(r.segmentation.precision(), 0.45) << r.cell;
    }
  }
}

// The cell-based growing order (grow.cell_px = 8, through the presets' overrides) holds the
// same acceptance bounds on the reduced protocol.
TEST(Table1Protocol, CellGrowingOrderMeetsTheBounds) {
  ProtocolOptions o;
  o.methods = {Method::Pgc};
  o.frames_per_cell = 3;
  o.preset_overrides = {"grow.cell_px=8"};
  EXPECT_EQ(preset_parameters(o, "lab").get(grow_keys::cell_px), 8);
  EXPECT_EQ(preset_parameters(o, "field").get(grow_keys::cell_px), 8);
  const auto rs = run_table1(o);
  ASSERT_EQ(rs.size(), 6u);
  for (const BoundCheck& b : check_table1_bounds(rs, false))
    EXPECT_TRUE(b.pass) << b.name << ": measured " << b.value << ", limit " << b.limit;
  o.preset_overrides = {"grow.cell_px=99"};
  EXPECT_THROW(preset_parameters(o, "lab"), ParameterError);
}

// The speed bound on the paper's full-resolution R&L: one lab frame. The ratio is ~100x here,
// so load on a CI machine affecting both runs alike does not bring it near 30x.
TEST(EvaluateCli, WritesTheThreeReportFilesAndRejectsBadOptions) {
  IoTempDir tmp;
  const auto run = testing::run_cli("evaluate --protocol ci --methods pgc,qhull --frames 1 -q --out " + tmp.file("out"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* f : {"table1.md", "results.csv", "table1.png"})
    EXPECT_TRUE(std::filesystem::exists(tmp.file(std::string("out/") + f))) << f;
  EXPECT_EQ(testing::count_lines(testing::slurp(tmp.file("out/results.csv"))), 13);
  EXPECT_EQ(testing::run_cli("evaluate --methods pgc,hough --out " + tmp.file("x")).exit_code, 2);
  EXPECT_EQ(testing::run_cli("evaluate --protocol bogus --out " + tmp.file("x")).exit_code, 2);
  const auto bad_set = testing::run_cli("evaluate --protocol ci --set grow.cell_px=99 --out " + tmp.file("y"));
  EXPECT_EQ(bad_set.exit_code, 2);
  EXPECT_NE(bad_set.err.find("grow.cell_px"), std::string::npos) << bad_set.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("y/table1.md")));
  EXPECT_EQ(testing::run_cli("evaluate --dataset " + tmp.file("nowhere") + " --out " + tmp.file("x")).exit_code, 3);
}

}  // namespace
}  // namespace tunnelmap
