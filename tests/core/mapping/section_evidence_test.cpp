// A new section needs its step measured within single frames of two pose groups.
#include "core/mapping/section_evidence.h"

#include <gtest/gtest.h>

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
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, views, {0, 0, 1}, kChange);
  ASSERT_EQ(kept.sections.size(), 2u);
  EXPECT_EQ(kept.sections[1].first, 10);
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
  const SectionSplit kept = keep_confirmed_joints(p.split, p.w, p.h, views, {0, 1, 2, 3, 4}, kChange);
  ASSERT_EQ(kept.sections.size(), 1u);
  EXPECT_EQ(kept.sections[0].first, 0);
  EXPECT_EQ(kept.sections[0].last, 19);
}

TEST(SectionEvidence, OnePoseGroupsViewIsNotEnoughNorIsAStepTheOtherWay) {
  const Profile p;
  std::vector<FrameStationSize> one_group, wrong_way;
  add_frame(one_group, 0, 4, 14, 0.03);
  add_frame(one_group, 1, 5, 15, 0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, one_group, {3, 3}, kChange).sections.size(), 1u);
  // With two groups the same views make a joint: the rule counts poses, not frames.
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, one_group, {3, 4}, kChange).sections.size(), 2u);
  add_frame(wrong_way, 0, 4, 14, -0.03);
  add_frame(wrong_way, 1, 5, 15, -0.03);
  EXPECT_EQ(keep_confirmed_joints(p.split, p.w, p.h, wrong_way, {0, 1}, kChange).sections.size(), 1u);
}

}  // namespace
}  // namespace tunnelmap
