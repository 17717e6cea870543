// Stations on a girder that curves, rises and rolls: a simulated girder on a 150 m radius with
// a 4 % gradient and 3 degrees of cross-fall, mapped as `map` maps it and scored against the
// simulator's truth (core/evaluation/girder_scoring.h): station widths and heights, and the map's
// centre line against the true one (arc length and position).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/evaluation/girder_scoring.h"
#include "core/io/dataset.h"
#include "core/mapping/dataset_mapping.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;

struct Spread {
  double mean = 0, p95 = 0, worst = 0;
};

Spread spread(std::vector<double> v) {
  Spread s;
  if (v.empty()) return s;
  for (double& x : v) x = std::abs(x), s.mean += x;
  std::sort(v.begin(), v.end());
  s.mean /= v.size();
  s.p95 = v[std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * v.size())) - 1)];
  s.worst = v.back();
  return s;
}

// A girder of `length_m` on the curve, walked from end to end with two frames per stop.
SimConfig curved_girder(double length_m, bool drift) {
  SimConfig c = SimConfig::from_preset("field");
  c.seed = 7;
  c.width_m = 0.9;
  c.height_m = 1.2;
  c.girder_length_m = length_m;
  c.diaphragm_spacing_m = 4.0;
  c.curve_radius_m = 150.0;
  c.gradient_pct = 4.0;
  c.cross_fall_deg = 3.0;
  if (drift) c.drift_translation_mm_per_sqrt_m = 10.0, c.drift_rotation_deg_per_sqrt_m = 0.2;
  SimWalk walk;
  walk.start_x_m = 0.4;
  walk.end_x_m = length_m - 1.0;
  walk.stops = static_cast<int>(std::lround((walk.end_x_m - walk.start_x_m) / 0.6)) + 1;
  walk.pose = {0.05, 0.5, 0.0, 2.0, -2.0};
  walk.through_openings = true;
  c.walk = walk;
  c.frames = 2 * walk.stops;
  return c;
}

struct Mapped {
  GirderScore score;
  Dataset dataset;
  DatasetMapping mapping;
};

Mapped map_girder(const SimConfig& c, const IoTempDir& tmp, const std::vector<std::string>& overrides = {}) {
  const std::string dir = tmp.file("girder");
  write_sim_dataset(dir, c);
  Mapped m;
  m.dataset = read_dataset(dir);
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  params.set_from_strings(overrides);
  Pipeline pipeline(params);
  m.mapping = map_dataset(m.dataset, pipeline, true);
  m.score = score_girder(m.mapping, m.dataset.ground_truth, m.dataset.raw["frames"]);
  return m;
}

// The map's centre line against the truth's: per measured point, its distance from the true
// centre line, and its station against the true arc length there (after one common offset:
// the map counts stations from its first frame, the truth from the girder's start wall).
struct CentrelineError {
  std::vector<double> station_mm, offset_mm;
};

CentrelineError centreline_error(const StationMap& map, const nlohmann::json& truth_line) {
  std::vector<double> s_true;
  std::vector<Eigen::Vector3d> x_true;
  for (const auto& p : truth_line)
    s_true.push_back(p["station_m"].get<double>()),
        x_true.push_back({p["point"][0].get<double>(), p["point"][1].get<double>(), p["point"][2].get<double>()});
  CentrelineError e;
  std::vector<double> along;
  for (const CentrelinePoint& c : map.girder.centreline) {
    if (c.source != "measured") continue;
    std::size_t best = 0;
    for (std::size_t i = 1; i < x_true.size(); ++i)
      if ((x_true[i] - c.point).squaredNorm() < (x_true[best] - c.point).squaredNorm()) best = i;
    const std::size_t a = best == 0 ? 0 : best - 1, b = std::min(x_true.size() - 1, best + 1);
    const Eigen::Vector3d dir = (x_true[b] - x_true[a]).normalized();
    const Eigen::Vector3d d = c.point - x_true[best];
    along.push_back(c.station_m - (s_true[best] + dir.dot(d)));
    e.offset_mm.push_back((d - dir * dir.dot(d)).norm() * 1000);
  }
  std::vector<double> sorted = along;
  std::sort(sorted.begin(), sorted.end());
  const double offset = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  for (double a : along) e.station_mm.push_back((a - offset) * 1000);
  return e;
}

void print(const char* what, const GirderScore& g) {
  const Spread w = spread(g.width_error_mm), h = spread(g.height_error_mm);
  std::printf("%s: %zu stations; width %.2f / %.2f / %.2f mm, height %.2f / %.2f / %.2f mm\n", what,
              g.width_error_mm.size(), w.mean, w.p95, w.worst, h.mean, h.p95, h.worst);
}

// A short girder, one frame per stop, exact poses: the station bounds of the contract (mean 3 mm,
// p95 8 mm), the centre line's stations against the true arc length and its points against the
// true centre.
TEST(CurvedGirder, StationsFollowA150MetreCurveThatRisesAndRolls) {
  IoTempDir tmp;
  SimConfig c = curved_girder(10.0, false);
  c.frames = c.walk->stops;
  const Mapped m = map_girder(c, tmp);
  const Spread w = spread(m.score.width_error_mm), h = spread(m.score.height_error_mm);
  ASSERT_GT(m.score.width_error_mm.size(), 30u);
  ASSERT_GT(m.score.height_error_mm.size(), 30u);
  EXPECT_LE(w.mean, 3.0);
  EXPECT_LE(w.p95, 8.0);
  EXPECT_LE(h.mean, 3.0);
  EXPECT_LE(h.p95, 8.0);
  const CentrelineError e =
      centreline_error(m.mapping.mapped.stations, m.dataset.ground_truth["girder"]["centreline"]);
  ASSERT_GT(e.station_mm.size(), 30u);
  const Spread s = spread(e.station_mm), o = spread(e.offset_mm);
  // Along the first frame's straight axis the stations would be short by s^3 / (6 R^2), 5 mm at 9 m.
  EXPECT_LE(s.worst, 2.0);
  EXPECT_LE(o.mean, 3.0);
  EXPECT_LE(o.worst, 8.0);
  print("10 m, exact", m.score);
  std::printf("  centre line: station %.1f / %.1f / %.1f mm, off the true line %.1f / %.1f / %.1f mm\n", s.mean,
              s.p95, s.worst, o.mean, o.p95, o.worst);
}

// A curve that climbs turns about the world's up at every plate. Against the girder's own up
// that turn has a part about the girder's axis (the gradient times the turn: 0.06 degrees at
// each plate 4 m apart on R 150 m at 4 %), always the same way, so walls whose roll across a
// plate was held against the girder's up rolled the map a little more at every plate. Held
// against the world's up they stay level. Exact poses, corrected whatever the evidence, so
// that a bias of the walls' ties shows.
TEST(CurvedGirder, TheMapDoesNotRollAtThePlatesOfACurveThatClimbs) {
  IoTempDir tmp;
  SimConfig c = curved_girder(24.0, false);
  c.frames = c.walk->stops;
  const Mapped m = map_girder(c, tmp, {"slam.correction_sigmas=0"});
  ASSERT_EQ(m.score.poses_kept, std::optional<bool>(false));
  double worst_roll_deg = 0.0;
  int scored = 0;
  for (const FramePoseError& e : m.score.frame_pose_errors)
    if (e.split) worst_roll_deg = std::max(worst_roll_deg, std::abs(e.roll_deg)), ++scored;
  ASSERT_GT(scored, 30);
  std::printf("worst roll of the corrected exact poses: %.3f deg\n", worst_roll_deg);
  EXPECT_LT(worst_roll_deg, 0.11);  // measured 0.048 (0.18 held against the girder's up)
}

// A girder on a curve is a chain of straight compartments that kinks at its plates. A wall band
// with a plate inside is then two surfaces, not one plane: fitted as one, it leans towards the
// side a frame saw more of, frame after frame differently, and exact poses looked wrong (on a
// 100 m girder on R 150 m the structure's evidence for a correction was 1.4 times what noise
// gives). Cut at the plates, the walls agree with exact poses, which stay as given.
TEST(CurvedGirder, ExactPosesOnAGirderThatKinksAtItsPlatesAreKept) {
  IoTempDir tmp;
  SimConfig c = curved_girder(24.0, false);
  c.frames = c.walk->stops;
  const Mapped m = map_girder(c, tmp);
  const CorrectionEvidence& e = m.mapping.mapped.refinement.evidence;
  ASSERT_GT(e.dof, 100);
  std::printf("evidence for a correction: %.0f for %d degrees of freedom (threshold %.0f)\n", e.chi2_gain, e.dof,
              e.threshold);
  EXPECT_EQ(m.score.poses_kept, std::optional<bool>(true));
  EXPECT_LT(e.chi2_gain, e.dof);  // noise alone gives about dof
}

// A measurement for docs/tunnel-map.md (about a minute per run in Release):
// --gtest_also_run_disabled_tests --gtest_filter='*ThirtyMetre*'.
TEST(CurvedGirder, DISABLED_ThirtyMetreGirderMeasured) {
  for (const bool drift : {false, true}) {
    IoTempDir tmp;
    const Mapped m = map_girder(curved_girder(30.0, drift), tmp);
    print(drift ? "30 m, drift" : "30 m, exact", m.score);
    const CentrelineError c =
        centreline_error(m.mapping.mapped.stations, m.dataset.ground_truth["girder"]["centreline"]);
    const Spread s = spread(c.station_mm), o = spread(c.offset_mm);
    std::printf("  centre line: %zu points; station %.1f / %.1f / %.1f mm, off the true line %.1f / %.1f / %.1f mm\n",
                c.station_mm.size(), s.mean, s.p95, s.worst, o.mean, o.p95, o.worst);
  }
}

}  // namespace
}  // namespace tunnelmap
