// An IMU's gravity per frame holds the map's tilt: a drifted walk mapped with it ends closer to
// the truth vertically and in its tilt than without it, and exact poses stay as given.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/evaluation/girder_scoring.h"
#include "core/io/dataset.h"
#include "core/mapping/dataset_mapping.h"
#include "core/mapping/gravity_agreement.h"
#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"
#include "tests/support/girder_walk_config.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;

// 16 m, plates every 4 m, a stop every 0.5 m; the odometry drifts 10 mm and 0.5 degrees per
// square-root metre; the IMU's gravity is good to 0.1 degrees.
SimConfig drifted_walk_with_imu() {
  SimConfig c = testing::girder_walk_config(16.0, 4.0, 31);
  c.drift_translation_mm_per_sqrt_m = 10.0;
  c.drift_rotation_deg_per_sqrt_m = 0.5;
  c.imu_gravity_deg = 0.1;
  c.seed = 11;
  return c;
}

Pipeline field_pipeline() {
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_TEST_DATA_DIR) + "/presets/field.json");
  return Pipeline(params);
}

GirderScore mapped(const Dataset& ds) {
  Pipeline pipeline = field_pipeline();
  return score_girder(map_dataset(ds, pipeline, true), ds.ground_truth, ds.raw["frames"]);
}

// The frames' gravity against the poses mapped with it.
GravityAgreement agreement_when_mapped(const Dataset& ds) {
  Pipeline pipeline = field_pipeline();
  const DatasetMapping dm = map_dataset(ds, pipeline, true);
  return gravity_agreement(dm.mapped.poses, dataset_gravity(ds), ds.up);
}

double p95(std::vector<double> v) {
  for (double& x : v) x = std::abs(x);
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::ceil(0.95 * v.size())) - 1];
}

TEST(ImuGravity, ADriftedWalkMappedWithItsGravityEndsCloserToTheTruthVerticallyAndInItsTilt) {
  IoTempDir tmp;
  write_sim_dataset(tmp.file("walk"), drifted_walk_with_imu());
  const Dataset with = read_dataset(tmp.file("walk"));
  Dataset without = with;
  for (DatasetFrameRef& f : without.frames) f.gravity.reset();
  const GirderScore a = mapped(with), b = mapped(without);
  std::vector<double> tilt_a, tilt_b;
  for (const FramePoseError& e : a.frame_pose_errors) tilt_a.push_back(std::hypot(e.roll_deg, e.pitch_deg));
  for (const FramePoseError& e : b.frame_pose_errors) tilt_b.push_back(std::hypot(e.roll_deg, e.pitch_deg));
  std::printf("p95 with / without the IMU: vertical %.2f / %.2f mm, tilt %.3f / %.3f deg\n",
              p95(a.pose_error_vertical_mm), p95(b.pose_error_vertical_mm), p95(tilt_a), p95(tilt_b));
  EXPECT_LT(p95(tilt_a), 0.5 * p95(tilt_b));
  // The IMU's own noise: a tilt of 0.1 degrees on each of two axes is 0.245 degrees at p95.
  EXPECT_LT(p95(tilt_a), 0.245);
  EXPECT_LT(p95(a.pose_error_vertical_mm), p95(b.pose_error_vertical_mm));
}

TEST(ImuGravity, AnImuNoisierThanTheEstimateWeighsItIsToldWithItsNoise) {
  // The walk's IMU at 1 degree per axis where slam.gravity_deg says 0.1: the walls hold the
  // tilt, so the frames' gravity stays about its own noise away from the mapped poses' down.
  IoTempDir tmp;
  SimConfig c = drifted_walk_with_imu();
  c.imu_gravity_deg = 1.0;
  write_sim_dataset(tmp.file("walk"), c);
  const GravityAgreement noisy = agreement_when_mapped(read_dataset(tmp.file("walk")));
  ASSERT_TRUE(noisy.per_axis_deg());
  std::printf("IMU at 1 deg: %.3f deg per axis over %d frames\n", *noisy.per_axis_deg(), noisy.frames);
  EXPECT_GT(*noisy.per_axis_deg(), 0.5);
  EXPECT_LT(*noisy.per_axis_deg(), 1.5);
  const std::string note = gravity_noise_note(noisy, 0.1);
  EXPECT_NE(note.find("more than 3 x slam.gravity_deg = 0.1"), std::string::npos) << note;
  // The CLI, the GUI and the report show the same line: it names the parameter, not a flag.
  EXPECT_NE(note.find("slam.gravity_deg set to"), std::string::npos) << note;
  EXPECT_EQ(note.find("--set"), std::string::npos) << note;
  EXPECT_TRUE(gravity_noise_note(noisy, 1.0).empty());  // weighed as it is

  // At 0.1 degrees, as the estimate weighs it: nothing to tell.
  IoTempDir good;
  write_sim_dataset(good.file("walk"), drifted_walk_with_imu());
  const GravityAgreement fine = agreement_when_mapped(read_dataset(good.file("walk")));
  ASSERT_TRUE(fine.per_axis_deg());
  EXPECT_LT(*fine.per_axis_deg(), 0.2);
  EXPECT_TRUE(gravity_noise_note(fine, 0.1).empty());
}

TEST(ImuGravity, ExactPosesWithANoisyGravityAreKeptAsGiven) {
  IoTempDir tmp;
  SimConfig c = drifted_walk_with_imu();
  c.drift_translation_mm_per_sqrt_m = c.drift_rotation_deg_per_sqrt_m = 0.0;
  write_sim_dataset(tmp.file("walk"), c);
  const GirderScore s = mapped(read_dataset(tmp.file("walk")));
  ASSERT_TRUE(s.poses_kept);
  EXPECT_TRUE(*s.poses_kept);
  EXPECT_LT(p95(s.pose_error_mm), 0.01);
}

}  // namespace
}  // namespace tunnelmap
