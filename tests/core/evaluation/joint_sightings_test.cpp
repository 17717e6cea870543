// Where the frames of a simulated girder saw the walls that step at its joints: a roof that rises
// just past a plate is out of every frame's view for a stretch beyond the plate, while a wider
// section in the middle of a compartment is seen right up to its joint from both sides.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/evaluation/joint_sightings.h"
#include "core/io/dataset.h"
#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/support/girder_walk_config.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;

// 12 m, plates every 4 m, a stop every 0.5 m through the manholes. The roof rises 30 mm 5 cm
// past the plate at 4 m; the section widens by 30 mm at 6 m, half-way to the next plate.
SimConfig two_joints() {
  SimConfig c = testing::girder_walk_config(12.0, 4.0, 23);
  c.sections = {{4.05, 0.84, 1.20}, {1.95, 0.84, 1.23}, {6.0, 0.87, 1.23}};
  c.sections_start_x_m = 0.0;
  return c;
}

// The girder is simulated once for the suite.
class JointSightings : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new IoTempDir;
    write_sim_dataset(tmp_->file("girder"), two_joints());
    ds_ = new Dataset(read_dataset(tmp_->file("girder")));
  }
  static void TearDownTestSuite() {
    delete ds_;
    delete tmp_;
  }
  static const Dataset& ds() { return *ds_; }
  static TruthLine line() { return TruthLine(ds_->ground_truth["girder"]["centreline"]); }

 private:
  static IoTempDir* tmp_;
  static Dataset* ds_;
};
IoTempDir* JointSightings::tmp_ = nullptr;
Dataset* JointSightings::ds_ = nullptr;

TEST_F(JointSightings, ARoofRisingPastAPlateIsUnseenOverAStretchAndAMidCompartmentStepIsSeenAtItsJoint) {
  const std::vector<JointSighting> seen = joint_sightings(ds(), line(), {4.05, 6.0});
  ASSERT_EQ(seen.size(), 2u);
  for (const JointSighting& s : seen)
    std::printf("joint at %.2f m: seen before it to %.3f m, after it from %.3f m\n", s.joint_m, s.seen_before_m,
                s.seen_after_m);
  // Past the plate: the roof before the joint is seen up to the plate (5 cm short of the joint),
  // the raised roof only from beyond the camera's field of view at the first stops past it.
  EXPECT_NEAR(seen[0].seen_before_m, 4.0, 0.06);
  EXPECT_GT(seen[0].seen_after_m - 4.05, 0.5);
  EXPECT_FALSE(seen[0].seen_within(0.2));
  // Mid-compartment: both side walls seen within a 5 cm bin of the joint on either side.
  EXPECT_NEAR(seen[1].seen_before_m, 6.0, 0.05);
  EXPECT_NEAR(seen[1].seen_after_m, 6.0, 0.05);
  EXPECT_TRUE(seen[1].seen_within(0.2));
}

TEST_F(JointSightings, NoneWhenTheSectionsDoNotMatchTheJointsOrTheFramesHaveNoLabels) {
  EXPECT_TRUE(joint_sightings(ds(), line(), {4.05}).empty());
  Dataset unlabelled = ds();
  for (DatasetFrameRef& f : unlabelled.frames) f.gt_path.clear();
  EXPECT_TRUE(joint_sightings(unlabelled, line(), {4.05, 6.0}).empty());
}

TEST_F(JointSightings, ScoresCountOnlyTheJointsSeenWithinTheTolerance) {
  GirderScore g;
  g.joint_station_m = {4.05, 6.0};
  g.joint_found = {false, true};
  score_joint_sightings(ds(), GirderScoringOptions{}, g);
  ASSERT_TRUE(g.joints_seen && g.joints_found_of_seen);
  EXPECT_EQ(*g.joints_seen, 1);
  EXPECT_EQ(*g.joints_found_of_seen, 1);
  ASSERT_EQ(g.joint_seen_after_m.size(), 2u);
  EXPECT_GT(g.joint_seen_after_m[0], 4.5);
}

}  // namespace
}  // namespace tunnelmap
