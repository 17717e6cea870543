// The run engine: the context rule (the station map for posed frames, so a real section change
// is followed, not rejected), parallel runs equal to serial ones, cancellation, and a single
// frame re-run from the first stage a parameter change affects, equal to a full run.
#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/Geometry>

#include "core/engine/frame_run.h"
#include "core/engine/run_engine.h"
#include "core/io/json_file.h"
#include "core/planes/grow_options.h"
#include "core/report/results_json.h"
#include "core/tunnel/tunnel_options.h"
#include "core/util/build_paths.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_cli_fixture.h"

using namespace tunnelmap;
using namespace tunnelmap::testing;

namespace {

const std::string kLabPreset = std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/lab.json";

// A posed walk over two sections of different width, simulated once per build and shared by
// every test here (they only read it).
class SectionWalkEngine : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    shared = shared_cli_fixture(
        "SectionWalkEngine", {{"simulate", "simulate {dir}/walk --preset lab --frames 16 --seed 3 --quiet"
                                           " --sections 1.2:0.84x1.30,2:0.78x1.28 --walk -0.6,2.4,6"
                                           " --walk-pose 0,0.5,0"}});
    ASSERT_TRUE(shared.ok()) << shared.error;
  }
  static RunSettings lab_settings(int threads) {
    RunSettings s;
    s.params.load_json_file(kLabPreset);
    s.threads = threads;
    return s;
  }
  // Every frame's results JSON, timings aside.
  static std::vector<nlohmann::json> run_all(const FrameSource& source, RunEngine& engine) {
    std::vector<nlohmann::json> frames;
    engine.run(source, [&](SequenceFrame& f) {
      EXPECT_TRUE(f.ok()) << f.error_message;
      nlohmann::json j = detection_frame_json(f.index, f.frame.source, f.result);
      j.erase("timings_ms");
      frames.push_back(std::move(j));
      return true;
    });
    return frames;
  }
  static SharedFixture shared;
};
SharedFixture SectionWalkEngine::shared;

TEST_F(SectionWalkEngine, PosedFramesFollowTheSectionChangeThroughTheStationMap) {
  const auto source = open_input(shared.file("walk"), ReadOptions());
  ASSERT_NE(source->dataset(), nullptr);
  const nlohmann::json truth = read_json_file(shared.file("walk/dataset.json"))["ground_truth"]["sections"];
  ASSERT_EQ(truth.size(), 2u);
  RunEngine engine(lab_settings(2), source.get());
  const std::vector<nlohmann::json> frames = run_all(*source, engine);
  ASSERT_EQ(frames.size(), 16u);
  EXPECT_EQ(engine.context().stations().frames(), 16);  // every frame went into the map
  int detected = 0, rejected = 0;
  for (const auto& f : frames) {
    detected += f["detected"].get<bool>();
    rejected += f["status"] == "inconsistent_with_context";
  }
  // The recent-frames context would reject the narrower section; the station map follows it.
  EXPECT_EQ(rejected, 0);
  EXPECT_GE(detected, 15);
  double narrow = 1.0, wide = 0.0;
  for (const auto& f : frames)
    if (f["width_source"] == "measured") {
      narrow = std::min(narrow, f["width_m"].get<double>());
      wide = std::max(wide, f["width_m"].get<double>());
    }
  EXPECT_NEAR(wide, 0.84, 0.012);
  EXPECT_NEAR(narrow, 0.78, 0.012);
}

TEST_F(SectionWalkEngine, TwoThreadsEqualOneFieldForField) {
  const auto source = open_input(shared.file("walk"), ReadOptions());
  RunEngine serial(lab_settings(1), source.get()), parallel(lab_settings(2), source.get());
  EXPECT_EQ(run_all(*source, parallel), run_all(*source, serial));
}

TEST_F(SectionWalkEngine, CancelStopsTheRunAfterTheFrameBeingDelivered) {
  const auto source = open_input(shared.file("walk"), ReadOptions());
  RunEngine engine(lab_settings(2), source.get());
  std::size_t delivered = 0, last_progress = 0;
  const SequenceStats stats = engine.run(
      *source,
      [&](SequenceFrame& f) {
        if (++delivered == 3) engine.cancel();
        return f.ok();
      },
      [&](std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 16u);
        last_progress = done;
      });
  EXPECT_TRUE(stats.stopped);
  EXPECT_EQ(delivered, 3u);
  EXPECT_EQ(last_progress, 3u);
  EXPECT_TRUE(engine.cancelled());
}

// Frame `index` of another source as a sequence of its own.
class OneFrame : public FrameSource {
 public:
  OneFrame(const FrameSource& source, std::size_t index) : source_(source), index_(index) {}
  std::size_t size() const override { return 1; }
  DepthFrame load(std::size_t) const override { return source_.load(index_); }
  std::string describe(std::size_t) const override { return source_.describe(index_); }
  const Dataset* dataset() const override { return source_.dataset(); }

 private:
  const FrameSource& source_;
  std::size_t index_;
};

// The GUI's frame view and `render` show a posed frame as `detect` on that frame alone gives it:
// placed by its pose, with the sections it sees itself.
TEST_F(SectionWalkEngine, AFrameViewedOnItsOwnIsWhatTheEngineGivesForThatFrameAlone) {
  const auto source = open_input(shared.file("walk"), ReadOptions());
  int with_parts = 0;
  for (std::size_t k : {0u, 6u, 9u, 15u}) {
    FrameRun viewed;
    run_frame(*source, k, lab_settings(1), viewed);
    nlohmann::json view = detection_frame_json(k, "", viewed.result);
    view.erase("timings_ms");
    const OneFrame alone(*source, k);
    RunEngine engine(lab_settings(1), &alone);
    std::vector<nlohmann::json> ran = run_all(alone, engine);
    ASSERT_EQ(ran.size(), 1u);
    ran[0]["index"] = k;
    ran[0]["source"] = "";
    EXPECT_EQ(view, ran[0]) << "frame " << k;
    with_parts += view["parts"].size() > 1;
    // A slider's re-run from the tunnel stage places the frame again, as a full run does.
    RunSettings designed = lab_settings(1);
    designed.params.set(tunnel_keys::design_width_m, 0.82);
    designed.params.set(tunnel_keys::design_height_m, 1.30);
    const RunSettings before = lab_settings(1);
    ASSERT_EQ(run_frame(*source, k, designed, viewed, &before), Stage::Tunnel);
    FrameRun full;
    run_frame(*source, k, designed, full);
    nlohmann::json rerun_json = detection_frame_json(k, "", viewed.result), full_json = detection_frame_json(k, "", full.result);
    rerun_json.erase("timings_ms");
    full_json.erase("timings_ms");
    EXPECT_EQ(rerun_json, full_json) << "frame " << k;
  }
  EXPECT_GE(with_parts, 1);  // a frame that sees the section change, whose own parts set its size
}

TEST(FirstChangedStage, IsTheEarliestStageOfAnyChangedParameter) {
  Parameters a, b;
  EXPECT_FALSE(first_changed_stage(a, b));
  b.set(tunnel_keys::design_width_m, 0.82);
  EXPECT_EQ(first_changed_stage(a, b), Stage::Tunnel);
  b.set(grow_keys::distance_mm, 20.0);
  EXPECT_EQ(first_changed_stage(a, b), Stage::Planes);
}

TEST(RunFrame, ARerunFromTheChangedStageEqualsAFullRun) {
  const auto source = open_input(std::string(TUNNELMAP_TEST_DATA_DIR) + "/sample/lab/depth/000000.png", ReadOptions());
  RunSettings before;
  before.params.load_json_file(kLabPreset);
  FrameRun run;
  EXPECT_EQ(run_frame(*source, 0, before, run), Stage::Cloud);
  ASSERT_TRUE(run.result.map.detected);
  RunSettings after = before;
  after.params.set(tunnel_keys::design_width_m, 0.82);
  after.params.set(tunnel_keys::design_height_m, 1.30);
  EXPECT_EQ(run_frame(*source, 0, after, run, &before), Stage::Tunnel);
  FrameRun full;
  EXPECT_EQ(run_frame(*source, 0, after, full), Stage::Cloud);
  nlohmann::json rerun_json = detection_frame_json(0, "", run.result), full_json = detection_frame_json(0, "", full.result);
  rerun_json.erase("timings_ms");
  full_json.erase("timings_ms");
  EXPECT_EQ(rerun_json, full_json);
  // Another method re-runs the whole frame.
  RunSettings qhull = after;
  qhull.method = Method::Qhull;
  EXPECT_EQ(run_frame(*source, 0, qhull, run, &after), Stage::Cloud);
}

}  // namespace

// Rigid alignment, then the mean distance across the girder (which runs along x) of each camera
// centre from the truth's (the map's frame is the first pose's).
double across_error_mm(const std::vector<Eigen::Vector3d>& est, const std::vector<Eigen::Vector3d>& truth,
                       const std::vector<bool>& only = {}) {
  Eigen::Matrix3Xd a(3, est.size()), b(3, est.size());
  for (std::size_t i = 0; i < est.size(); ++i) a.col(i) = est[i], b.col(i) = truth[i];
  const Eigen::Isometry3d align(Eigen::umeyama(a, b, false));
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < est.size(); ++i)
    if (only.empty() || only[i]) sum += (align * est[i] - truth[i]).tail<2>().norm(), ++n;
  return n ? 1000.0 * sum / n : 0.0;
}

// A 12 m girder (plates every 4 m) walked through its manholes with odometry that drifts (10 mm
// and 0.2 degrees per square-root metre), localised while it runs: the mean error across the
// girder of the given poses and of the delivered ones.
struct AcrossErrors {
  double given_mm = 0.0, localised_mm = 0.0;
  double localised_back_mm = 0.0;  // of the frames whose camera looks back along the girder (-x)
};

AcrossErrors localised_across_girder(int seed, const std::string& walk_flags = "") {
  IoTempDir tmp;
  const CliRun sim = run_cli("simulate " + tmp.file("girder") + " --preset field --girder 12 --diaphragm-spacing 4"
                             " --frames 40 --drift 10,0.2 --quiet --seed " + std::to_string(seed) + " " + walk_flags);
  const auto source = sim.exit_code == 0 ? open_input(tmp.file("girder"), ReadOptions()) : nullptr;
  if (!source || !source->dataset()) {
    ADD_FAILURE() << "no simulated girder: " << sim.err;
    return {};
  }
  const nlohmann::json frames = read_json_file(tmp.file("girder/dataset.json"))["frames"];
  auto true_position = [&](std::size_t index) {
    const nlohmann::json t = frames[index]["pose_true"];
    return Eigen::Vector3d(t[3].get<double>(), t[7].get<double>(), t[11].get<double>());
  };
  auto looks_back = [&](std::size_t index) { return frames[index]["pose_true"][2].get<double>() < 0.0; };
  std::vector<Eigen::Vector3d> given, localised, truth, delivered_truth;
  std::vector<bool> delivered_back;
  for (std::size_t i = 0; i < source->dataset()->frames.size(); ++i) {
    EXPECT_TRUE(source->dataset()->frames[i].pose.has_value()) << i;
    given.push_back(source->dataset()->frames[i].pose->translation());
    truth.push_back(true_position(i));
  }
  RunSettings s;
  s.params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  s.params.set("slam.localise", true);
  RunEngine engine(s, source.get());
  engine.run(*source, [&](SequenceFrame& f) {
    EXPECT_TRUE(f.frame.pose.has_value());
    localised.push_back(f.frame.pose->translation());
    delivered_truth.push_back(true_position(f.index));
    delivered_back.push_back(looks_back(f.index));
    // A frame turned round to be localised is delivered in its own view: its axis ahead of its
    // camera, over the stretch it saw.
    if (f.result.map.detected) {
      EXPECT_GT(f.result.map.axis_dir.z(), 0.0) << f.index;
      EXPECT_GT(f.result.map.axis_point.z() + f.result.map.extent_min_m * f.result.map.axis_dir.z(), 0.0) << f.index;
    }
    return true;
  });
  EXPECT_EQ(localised.size(), given.size());
  const AcrossErrors e{across_error_mm(given, truth), across_error_mm(localised, delivered_truth),
                       across_error_mm(localised, delivered_truth, delivered_back)};
  std::printf("seed %d %s, across the girder: given poses %.1f mm, localised %.1f mm (mean; %.1f mm looking back)\n",
              seed, walk_flags.c_str(), e.given_mm, e.localised_mm, e.localised_back_mm);
  return e;
}

// Three seeds: with slam.localise every delivered frame carries the pose the structure mapped so
// far gave it, nearer the truth across the girder than the odometry's. The odometry's poses are
// the dataset's: without slam.localise the engine delivers them as given (FrameContext::apply),
// so they need no run of their own.
TEST(LocaliseWhileRunning, DeliveredPosesAreTheLocalisedOnesAndNearerTheTruth) {
  double given_sum = 0.0, localised_sum = 0.0;
  for (int seed : {5, 6, 7}) {
    const AcrossErrors e = localised_across_girder(seed);
    EXPECT_LT(e.localised_mm, e.given_mm) << seed;
    given_sum += e.given_mm;
    localised_sum += e.localised_mm;
  }
  EXPECT_GT(given_sum / 3, 5.0);  // the drift is there
  EXPECT_LT(localised_sum, 0.75 * given_sum);
}

// The same walks turning the camera round once per compartment past a plate: the frames that look
// back are localised with the walk's left and right (core/mapping/walk_facing.h).
TEST(LocaliseWhileRunning, AWalkThatLooksBackIsLocalisedAsOneThatLooksAhead) {
  double given_sum = 0.0, localised_sum = 0.0, back_sum = 0.0;
  for (int seed : {5, 6, 7}) {
    const AcrossErrors e = localised_across_girder(seed, "--look-back");
    EXPECT_LT(e.localised_mm, e.given_mm) << seed;
    given_sum += e.given_mm;
    localised_sum += e.localised_mm;
    back_sum += e.localised_back_mm;
  }
  EXPECT_LT(localised_sum, 0.75 * given_sum);
  // Named with the camera's left, the looks back were pulled sideways: twice the walk's error.
  EXPECT_LT(back_sum, 1.2 * localised_sum);
}

// The mean angle between where the delivered poses and the true ones put the world's up, degrees,
// of a simulated walk localised while it runs.
double localised_tilt_error_deg(const std::string& simulate_flags) {
  IoTempDir tmp;
  const CliRun sim = run_cli("simulate " + tmp.file("girder") + " " + simulate_flags + " --quiet");
  EXPECT_EQ(sim.exit_code, 0) << sim.err;
  const auto source = open_input(tmp.file("girder"), ReadOptions());
  const nlohmann::json frames = read_json_file(tmp.file("girder/dataset.json"))["frames"];
  RunSettings s;
  s.params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  s.params.set("slam.localise", true);
  RunEngine engine(s, source.get());
  double sum = 0.0;
  int n = 0;
  engine.run(*source, [&](SequenceFrame& f) {
    const nlohmann::json t = frames[f.index]["pose_true"];
    Eigen::Matrix3d R;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) R(r, c) = t[4 * r + c].get<double>();
    const Eigen::Vector3d up_true = R.transpose() * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d up = f.frame.pose->linear().transpose() * Eigen::Vector3d::UnitZ();
    sum += std::acos(std::clamp(up.dot(up_true), -1.0, 1.0)) * 180.0 / M_PI, ++n;
    return true;
  });
  return n ? sum / n : 0.0;
}

// The same walk (same seed, the same frames) with and without an IMU: while it runs, each
// frame's gravity holds its localised tilt.
TEST(LocaliseWhileRunning, AFramesGravityHoldsItsTiltWhileTheWalkRuns) {
  const std::string walk = "--preset field --girder 12 --diaphragm-spacing 4 --frames 40 --drift 10,0.5 --seed 5";
  const double without = localised_tilt_error_deg(walk), with = localised_tilt_error_deg(walk + " --imu 0.1");
  std::printf("localised tilt error (mean): %.3f deg without the IMU, %.3f deg with it\n", without, with);
  EXPECT_LT(with, 0.5 * without);
  EXPECT_LT(with, 0.15);  // a 0.1 degree tilt on each of two axes is 0.125 degrees on average
}
