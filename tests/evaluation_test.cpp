// The Table 1 evaluation (core/evaluation): segmentation metrics, report writers, sweeps, the
// symmetric zone prior, and the reduced CI protocol asserting the acceptance bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "core/evaluation/protocol.h"
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
// cell for R&L on every 8th pixel (its 100 iterations are slow by design). Asserts the issue's
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
      EXPECT_GT(r.segmentation.precision(), 0.6) << r.cell;
    }
  }
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
  EXPECT_EQ(testing::run_cli("evaluate --dataset " + tmp.file("nowhere") + " --out " + tmp.file("x")).exit_code, 3);
}

}  // namespace
}  // namespace tunnelmap
