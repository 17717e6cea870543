// The notes every front end shows: pose groups nothing checks, and an IMU noisier than weighed.
#include "core/mapping/mapping_notes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tunnelmap {
namespace {

PoseCorrection group(int id, std::vector<int> frames, std::vector<std::string> constrained) {
  PoseCorrection c;
  c.group = id;
  c.frames = std::move(frames);
  c.constrained = std::move(constrained);
  return c;
}

// Four frames at identity poses in a world whose up is +z; group 1 (frames 2-3) shares nothing.
MappedSequence walk_with_an_unchecked_stop() {
  MappedSequence m;
  m.refinement.ran = true;
  m.refinement.groups = {group(0, {0, 1}, {"x", "y"}), group(1, {2, 3}, {}), group(2, {4, 5}, {"z"})};
  m.poses.assign(6, Eigen::Isometry3d::Identity());
  return m;
}

TEST(MappingNotes, NamesEachPoseGroupNothingChecksWhenOthersAreChecked) {
  const MappingNotes notes = mapping_notes(walk_with_an_unchecked_stop(), {}, Eigen::Vector3d::UnitZ(), 0.1);
  ASSERT_EQ(notes.unchecked_poses.size(), 1u);
  EXPECT_EQ(notes.unchecked_poses[0],
            "pose 1 (frames 2-3): nothing it saw was seen from another pose, so nothing checks it; mapped where its "
            "pose puts it");
  EXPECT_TRUE(notes.gravity.empty());  // no IMU
  EXPECT_EQ(notes.all(), notes.unchecked_poses);
}

TEST(MappingNotes, NamesThePlatesOnlyAnUncheckedPoseSaw) {
  const MappedSequence walk = walk_with_an_unchecked_stop();
  const std::string head =
      "pose 1 (frames 2-3): nothing it saw was seen from another pose, so nothing checks it; mapped where its pose "
      "puts it";
  // A plate frame 4 (a checked pose) saw is no business of pose 1's line.
  const std::vector<std::string> one = unchecked_pose_notes(walk.refinement, {{14.5994, {3}}, {20.0, {4}}});
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], head + ", but for the plate it saw at station 14.599 m, which is not mapped");
  const std::vector<std::string> three =
      unchecked_pose_notes(walk.refinement, {{14.5994, {3}}, {18.25, {2, 3}}, {22.0, {2}}});
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three[0], head + ", but for the plates it saw at stations 14.599, 18.250 and 22.000 m, which are not mapped");
}

TEST(MappingNotes, NamesEachPlateSeenOnlyNearTheEndOfTheRangeAfterThePoses) {
  MappedSequence walk = walk_with_an_unchecked_stop();
  walk.stations.girder.plates_beyond_range = {{-0.0218, {4}}, {41.2104, {2, 3, 5}}};
  const MappingNotes notes = mapping_notes(walk, {}, Eigen::Vector3d::UnitZ(), 0.1);
  ASSERT_EQ(notes.plates_beyond_range.size(), 2u);
  const std::string tail =
      " was seen only near the end of the depth range, which places it too near, so it is not mapped; a frame "
      "nearer to it would map it";
  EXPECT_EQ(notes.plates_beyond_range[0], "the plate at about station -0.022 m (frame 4)" + tail);
  EXPECT_EQ(notes.plates_beyond_range[1], "the plate at about station 41.210 m (frames 2, 3 and 5)" + tail);
  const std::vector<std::string> all = notes.all();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0], notes.unchecked_poses[0]);
  EXPECT_EQ(all[2], notes.plates_beyond_range[1]);
}

TEST(MappingNotes, AWalkNothingTiesOrThatWasNotRefinedHasNoSuchNote) {
  MappedSequence none_tied = walk_with_an_unchecked_stop();
  for (PoseCorrection& c : none_tied.refinement.groups) c.constrained.clear();
  EXPECT_TRUE(mapping_notes(none_tied, {}, Eigen::Vector3d::UnitZ(), 0.1).all().empty());
  MappedSequence given = walk_with_an_unchecked_stop();
  given.refinement.ran = false;
  EXPECT_TRUE(mapping_notes(given, {}, Eigen::Vector3d::UnitZ(), 0.1).all().empty());
}

TEST(MappingNotes, AGravityTwoDegreesOffTheMappedDownIsNotedLast) {
  // Every frame's gravity tilted 2 degrees from the poses' down: 1.41 degrees per axis, more
  // than 3 x 0.1. Weighed at 1 degree it is within three times that: no note.
  const double tilt = 2.0 * M_PI / 180.0;
  const std::vector<std::optional<Eigen::Vector3d>> gravity(6, Eigen::Vector3d(std::sin(tilt), 0.0, -std::cos(tilt)));
  const MappingNotes noisy = mapping_notes(walk_with_an_unchecked_stop(), gravity, Eigen::Vector3d::UnitZ(), 0.1);
  ASSERT_FALSE(noisy.gravity.empty());
  EXPECT_NE(noisy.gravity.find("1.41 deg per tilt axis (RMS over 6 frames)"), std::string::npos) << noisy.gravity;
  ASSERT_EQ(noisy.all().size(), 2u);
  EXPECT_EQ(noisy.all().back(), noisy.gravity);
  EXPECT_TRUE(mapping_notes(walk_with_an_unchecked_stop(), gravity, Eigen::Vector3d::UnitZ(), 1.0).gravity.empty());
}

}  // namespace
}  // namespace tunnelmap
