// A new section needs its step measured within single frames of two pose groups.
#include "core/mapping/section_evidence.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace tunnelmap {
namespace {

constexpr double kChange = 0.012;

// Twenty stations: 0.80 m wide up to station 9, 0.83 m from station 10 (a real joint, or a
// step the pooled positions or one biased view made).
struct Profile {
  std::vector<double> w, h;
  SectionSplit split;
  Profile() {
    for (int k = 0; k < 20; ++k) {
      w.push_back(k < 10 ? 0.80 : 0.83);
      h.push_back(1.20);
    }
    split = split_sections(w, h, kChange, 3);
  }
};

JointEvidence evidence(std::vector<FrameStationSize> views, std::vector<int> pose_groups,
                       std::vector<int> plates = {}) {
  JointEvidence e;
  e.views = std::move(views);
  e.pose_groups = std::move(pose_groups);
  e.plate_stations = std::move(plates);
  e.change_m = kChange;
  return e;
}

// Frame `frame` measures stations lo..hi with its own walls: `base` wide, `step` more from 10.
void add_frame(std::vector<FrameStationSize>& views, int frame, int lo, int hi, double step, double base = 0.80) {
  for (int k = lo; k <= hi; ++k) views.push_back({frame, k, base + (k >= 10 ? step : 0.0), 1.20});
}

TEST(SectionEvidence, AStepTwoPoseGroupsMeasureInTheirOwnFramesIsAJoint) {
  const Profile p;
  ASSERT_EQ(p.split.sections.size(), 2u);
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 4, 14, 0.03);
  add_frame(views, 1, 5, 15, 0.03);  // same pose group as frame 0
  add_frame(views, 2, 6, 19, 0.03);
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 0, 1}));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 10);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, -1);  // seen whole
  EXPECT_NEAR(kept.sections[1].width_m, 0.83, 1e-9);
}

TEST(SectionEvidence, AStepNoFrameMeasuresItselfIsNoJoint) {
  // Frames past the joint see only the new size, frames before it see one size on both
  // sides, and one biased frame is 30 mm wide on both sides: the step exists only between
  // frames, where a pose error or a view's bias puts it.
  const Profile p;
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 0, 9, 0.0);
  add_frame(views, 1, 10, 19, 0.03);
  add_frame(views, 2, 11, 19, 0.03);
  add_frame(views, 3, 5, 15, 0.0);
  add_frame(views, 4, 6, 16, 0.0, 0.83);
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 3, 4}));
  ASSERT_EQ(kept.sections.size(), 1u);
  EXPECT_EQ(kept.sections[0].first, 0);
  EXPECT_EQ(kept.sections[0].last, 19);
}

TEST(SectionEvidence, OnePoseGroupsViewIsNotEnoughNorIsAStepTheOtherWay) {
  const Profile p;
  std::vector<FrameStationSize> one_group, wrong_way;
  add_frame(one_group, 0, 4, 14, 0.03);
  add_frame(one_group, 1, 5, 15, 0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(one_group, {3, 3})).sections.size(), 1u);
  // With two groups the same views make a joint: the rule counts poses, not frames.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(one_group, {3, 4})).sections.size(), 2u);
  add_frame(wrong_way, 0, 4, 14, -0.03);
  add_frame(wrong_way, 1, 5, 15, -0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(wrong_way, {0, 1})).sections.size(), 1u);
}

TEST(SectionEvidence, AFarViewThatBlursTheStepStillSeesIt) {
  // Its stations next to the joint average both sections, so its own step is 20 of 30 mm:
  // nearer the step than no step.
  const Profile p;
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 4, 14, 0.02);
  add_frame(views, 1, 4, 14, 0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1})).sections.size(), 2u);
  std::vector<FrameStationSize> small;
  add_frame(small, 0, 4, 14, 0.01);
  add_frame(small, 1, 4, 14, 0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(small, {0, 1})).sections.size(), 1u);
}

// A plate at station 8 hides the joint: frames before it see only 0.80, frames after only 0.83.
std::vector<FrameStationSize> views_either_side_of_a_plate() {
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 2, 7, 0.0);
  add_frame(views, 1, 3, 7, 0.0);
  add_frame(views, 2, 11, 19, 0.03);
  add_frame(views, 3, 12, 19, 0.03);
  return views;
}

TEST(SectionEvidence, AJointAPlateHidesIsKeptWhenPoseGroupsOnEachSideMeasureTheirSide) {
  // Nothing measured stations 8-10 (the plate, and the floor just past it): the joint lies
  // somewhere from 8 to 10 and goes to the middle, 9.
  Profile p;
  for (int k = 8; k <= 10; ++k) p.w[k] = p.h[k] = std::nan("");
  p.split = split_sections(p.w, p.h, kChange, 3);
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views_either_side_of_a_plate(), {0, 1, 2, 3}, {8}));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 9);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, 3);  // 8-10
  EXPECT_NEAR(kept.sections[0].width_m, 0.80, 1e-9);
  EXPECT_NEAR(kept.sections[1].width_m, 0.83, 1e-9);
}

TEST(SectionEvidence, AHiddenJointStaysUnseenWhenARunAfterItIsMergedBack) {
  // As above, and stations 17-19 measure 30 mm wider still in the pooled positions alone (no
  // frame sees that step): the run joins the section before it, whose joint a plate still hid.
  Profile p;
  for (int k = 8; k <= 10; ++k) p.w[k] = p.h[k] = std::nan("");
  for (int k = 17; k <= 19; ++k) p.w[k] = 0.86;
  p.split = split_sections(p.w, p.h, kChange, 3);
  ASSERT_EQ(p.split.sections.size(), 3u);
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views_either_side_of_a_plate(), {0, 1, 2, 3}, {8}));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 9);
  EXPECT_EQ(kept.sections[1].last, 19);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, 3);  // 8-10, not seen for having grown
}

TEST(SectionEvidence, APlateConfirmsNoJointWithoutTwoPoseGroupsOnEachSideOrWhenTwoSeeAcross) {
  const Profile p;
  const std::vector<FrameStationSize> views = views_either_side_of_a_plate();
  // No plate near the gap: the step lies between frames only.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 3}, {2})).sections.size(), 1u);
  // One pose group after the plate.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2}, {8})).sections.size(), 1u);
  // Frames of two pose groups measure both sides alike (0.80 on both): no step there to hide.
  std::vector<FrameStationSize> across = views;
  add_frame(across, 4, 5, 14, 0.0);
  add_frame(across, 5, 6, 13, 0.0);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(across, {0, 1, 2, 3, 4, 5}, {8})).sections.size(), 1u);
  // One group's view alone may be the one that is wrong (through a manhole, a wall and the
  // one past its joint a few millimetres in make one plane): the joint stays.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(across, {0, 1, 2, 3, 4, 4}, {8})).sections.size(), 2u);
}

TEST(SectionEvidence, AShortBiasedRunAtAPlateIsNoSection) {
  // Stations 9-11, just past a plate at 8, measure 30 mm wider in two pose groups' own frames
  // (a view of the plate's far side), then the girder's size again: one section.
  std::vector<double> w(20, 0.80), h(20, 1.20);
  for (int k = 9; k <= 11; ++k) w[k] = 0.83;
  const SectionSplit split = split_sections(w, h, kChange, 3);
  ASSERT_EQ(split.sections.size(), 3u);
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 2, 7, 0.0);
  add_frame(views, 1, 3, 7, 0.0);
  for (int frame : {2, 3})
    for (int k = 9; k <= 11; ++k) views.push_back({frame, k, 0.83, 1.20});
  add_frame(views, 4, 12, 19, 0.0);
  add_frame(views, 5, 13, 19, 0.0);
  const SectionSplit kept = keep_confirmed_joints(split, w, h, evidence(views, {0, 1, 2, 3, 4, 5}, {8}));
  ASSERT_EQ(kept.sections.size(), 1u);
  EXPECT_NEAR(kept.sections[0].width_m, 0.80, 1e-9);
}

// 1.20 m high up to station 11, 1.23 m from 12: the roof rises, the floor stays. A plate at 4
// hides stations 5-12 from every frame that measures the height whole; only the roof is seen
// at 9-12 (past the plate, the floor beside the camera is out of view).
struct RoofStep {
  std::vector<double> w = std::vector<double>(20, 0.80), h;
  std::vector<std::array<double, 4>> walls;
  std::vector<FrameStationSize> views;
  RoofStep() {
    const double nan = std::nan("");
    for (int k = 0; k < 20; ++k) {
      h.push_back(k <= 4 ? 1.20 : k >= 13 ? 1.23 : nan);
      const double roof = k >= 5 && k <= 8 ? nan : k < 12 ? 0.60 : 0.63;
      walls.push_back({0.40, 0.40, k >= 5 && k <= 12 ? nan : 0.60, roof});
    }
    for (int frame : {0, 1})
      for (int k = 0; k <= 4; ++k) views.push_back({frame, k, 0.80, 1.20});
    for (int frame : {2, 3})
      for (int k = 13; k <= 19; ++k) views.push_back({frame, k, 0.80, 1.23});
  }
  SectionSplit joints(const std::vector<std::array<double, 4>>& seen_walls) const {
    JointEvidence e = evidence(views, {0, 1, 2, 3}, {4});
    e.wall_m = seen_walls;
    return keep_confirmed_joints(split_sections(w, h, kChange, 3), w, h, e);
  }
};

TEST(SectionEvidence, TheWallThatCarriesAHiddenStepPlacesTheJoint) {
  const RoofStep r;
  const SectionSplit kept = r.joints(r.walls);
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 12);  // the roof moved between 11 and 12
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, 0);
  EXPECT_NEAR(kept.sections[0].height_m, 1.20, 1e-9);
  EXPECT_NEAR(kept.sections[1].height_m, 1.23, 1e-9);
}

TEST(SectionEvidence, AWallThatDoesNotStepLeavesAHiddenJointInTheMiddleOfItsStretch) {
  // Only the floor is seen past the plate: it stays where it was on both sides, so it cannot
  // tell the side; the joint goes to the middle of stations 5-12.
  RoofStep r;
  std::vector<std::array<double, 4>> floor_only = r.walls;
  for (int k = 5; k <= 12; ++k) floor_only[k][2] = 0.60, floor_only[k][3] = std::nan("");
  const SectionSplit kept = r.joints(floor_only);
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 9);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, 8);
}

TEST(SectionEvidence, AWallThatCarriesHalfAStepDoesNotPlaceTheJoint) {
  // The floor drops 15 mm and the roof rises 15 mm: each wall's half step is no more than the
  // centre line's error sideways, so the roof seen alone at 9-12 does not narrow the stretch.
  RoofStep r;
  for (int k = 0; k < 20; ++k) {
    if (k >= 12) r.walls[k][3] = 0.615;
    if (k >= 13) r.walls[k][2] = 0.615;
  }
  const SectionSplit kept = r.joints(r.walls);
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 9);
}

TEST(SectionEvidence, OnePoseThatSeesTheStepWithTwoPosesOnEachSideIsAJoint) {
  // The robot's one stop that saw the step whole (frames 2, 3), two stops before it that
  // measured only the first size and two after it that measured only the second.
  const Profile p;
  std::vector<FrameStationSize> views;
  const int first_station[6] = {0, 2, 5, 6, 10, 11}, last_station[6] = {9, 9, 15, 15, 19, 19};
  for (int frame = 0; frame < 6; ++frame)
    add_frame(views, frame, first_station[frame], last_station[frame], frame < 2 ? 0.0 : 0.03);
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2, 3, 4}));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 10);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, -1);
  // The same stop alone, with one stop on a side: no joint.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2, 3, 3})).sections.size(), 1u);
  // Frames of two other stops that see the size stay across contradict it: no joint. One
  // stop's view alone does not outweigh the stop that saw the step.
  add_frame(views, 6, 4, 14, 0.0);
  add_frame(views, 7, 5, 13, 0.0);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2, 3, 4, 5, 6})).sections.size(), 1u);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2, 3, 4, 5, 5})).sections.size(), 2u);
}

TEST(SectionEvidence, AViewWhoseFirstSizeEndsOneStationPastTheJointDoesNotTakeItBack) {
  // One stop sees the step (frames 2, 3), two stops on each side measure their side. Frames of
  // two more stops measure 0.80 m up to station 10, the first past the joint: the last
  // centimetres of the narrow section, put past the station's edge by their poses' error along
  // the girder. They saw one side only; the joint stays. Seen at 11 as well, the size stayed.
  const Profile p;
  std::vector<FrameStationSize> views;
  add_frame(views, 0, 0, 9, 0.0);
  add_frame(views, 1, 2, 9, 0.0);
  add_frame(views, 2, 5, 15, 0.03);
  add_frame(views, 3, 6, 15, 0.03);
  add_frame(views, 4, 10, 19, 0.03);
  add_frame(views, 5, 11, 19, 0.03);
  std::vector<FrameStationSize> edge = views, beyond = views;
  add_frame(edge, 6, 4, 10, 0.0);
  add_frame(edge, 7, 3, 10, 0.0);
  const std::vector<int> groups = {0, 1, 2, 2, 3, 4, 5, 6};
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(edge, groups));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 10);
  add_frame(beyond, 6, 4, 11, 0.0);
  add_frame(beyond, 7, 3, 11, 0.0);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(beyond, groups)).sections.size(), 1u);
}

TEST(SectionEvidence, AStepSeenFromBothSidesButNotWhereItLiesGoesToTheMiddleOfTheGap) {
  // Two stops measure 0.80 m at stations 4-7 and 0.83 m at 12-15 in their own frames; nothing
  // measured 8-11. The step is real, its place anywhere from 8 to 12: the joint goes to 10,
  // not to 12 where the new size was first measured.
  Profile p;
  for (int k = 8; k <= 11; ++k) p.w[k] = p.h[k] = std::nan("");
  p.split = split_sections(p.w, p.h, kChange, 3);
  ASSERT_EQ(p.split.sections.size(), 2u);
  ASSERT_EQ(p.split.sections[1].first, 12);
  std::vector<FrameStationSize> views;
  for (int frame : {0, 1}) {
    for (int k = 4; k <= 7; ++k) views.push_back({frame, k, 0.80, 1.20});
    for (int k = 12; k <= 15; ++k) views.push_back({frame, k, 0.83, 1.20});
  }
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1}));
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 10);
  EXPECT_EQ(kept.sections[1].unseen_joint_stations, 4);
}

}  // namespace
}  // namespace tunnelmap
