// A new section needs its step measured within single frames of two pose groups.
#include "core/mapping/section_evidence.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace tunnelmap

namespace tunnelmap {
namespace {

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

TEST(SectionEvidence, APlateConfirmsNoJointWithoutTwoPoseGroupsOnEachSideOrWhenAFrameSeesAcross) {
  const Profile p;
  const std::vector<FrameStationSize> views = views_either_side_of_a_plate();
  // No plate near the gap: the step lies between frames only.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 3}, {2})).sections.size(), 1u);
  // One pose group after the plate.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(views, {0, 1, 2, 2}, {8})).sections.size(), 1u);
  // A frame measures both sides alike (0.80 on both): no step there to hide.
  std::vector<FrameStationSize> across = views;
  add_frame(across, 4, 5, 14, 0.0);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, evidence(across, {0, 1, 2, 3, 4}, {8})).sections.size(), 1u);
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

}  // namespace
}  // namespace tunnelmap
