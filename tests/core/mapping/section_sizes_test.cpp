#include "core/mapping/section_sizes.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace tunnelmap {
namespace {

constexpr double kTolerance = 0.0085;  // two ties of 2 mm, 3 sigma

// One frame's view of a band: the left and right walls `width_m` apart and the roof and floor
// `height_m` apart, seen from a camera turned by `yaw` (the size is the frame's own, whatever
// its pose), each patch at `along_m` along the girder. With `inset_m` > 0 the frame also sees
// each wall's middle plate, that far inside.
std::vector<FramePatch> view(long band, double width_m, double height_m, double yaw = 0.0, double along_m = 1.0,
                             double inset_m = 0.0) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  std::vector<FramePatch> patches;
  const auto add = [&](int wall, const Eigen::Vector3d& outward, double distance_m) {
    for (double inset : {0.0, inset_m}) {
      FramePatch p;
      p.wall = wall;
      p.band = band;
      p.normal = R * outward;
      p.centroid = R * (outward * (distance_m - inset) + Eigen::Vector3d(0.0, 0.0, along_m));
      patches.push_back(p);
      if (!(inset_m > 0.0)) break;
    }
  };
  // Camera frame: x right, y down, z along the girder; the camera 0.1 m left of the middle.
  add(0, -Eigen::Vector3d::UnitX(), 0.5 * width_m - 0.1);
  add(1, Eigen::Vector3d::UnitX(), 0.5 * width_m + 0.1);
  add(2, -Eigen::Vector3d::UnitY(), 0.6);
  add(3, Eigen::Vector3d::UnitY(), height_m - 0.6);
  return patches;
}

// The change is not taken for one larger than the tolerance (NaN: not measured).
bool no_change(double change) { return !(std::abs(change) > kTolerance); }

TEST(SectionSizes, AChangeOfSectionIsMeasuredByEachFrameItself) {
  // Frames that see each wall's outer surface and its middle plate, 8 mm inside.
  SectionSizes sizes;
  sizes.record(view(3, 0.900, 1.200, 0.0, 1.0, 0.008));
  sizes.record(view(3, 0.9004, 1.2003, 0.2, 1.0, 0.008));
  sizes.record(view(6, 0.930, 1.200, -0.1, 2.0, 0.008));
  sizes.record(view(6, 0.9303, 1.2002, 0.05, 1.0, 0.008));
  EXPECT_NEAR(sizes.change(0, {3}, {6}, kTolerance), 0.030, 0.001);
  EXPECT_NEAR(sizes.change(1, {3}, {6}, kTolerance), 0.0, 0.001);  // the height did not change
}

TEST(SectionSizes, ASizeAPlatesThicknessShortIsNotTakenForAChange) {
  // Before the plate two frames saw the outer surfaces (0.900 m) and two took the left wall's
  // middle plate, 10 mm inside, for it (0.890 m); past the plate both frames saw that middle
  // plate only, which may be either: no change is measured.
  SectionSizes sizes;
  for (double w : {0.900, 0.9004, 0.890, 0.8903}) sizes.record(view(3, w, 1.2));
  for (double w : {0.890, 0.8902}) sizes.record(view(6, w, 1.2));
  EXPECT_TRUE(no_change(sizes.change(0, {3}, {6}, kTolerance)));
  // Past the plate the frames saw both as well: no change.
  for (double w : {0.9001, 0.9003}) sizes.record(view(6, w, 1.2));
  EXPECT_NEAR(sizes.change(0, {3}, {6}, kTolerance), 0.0, 0.001);
}

TEST(SectionSizes, OneSizeEitherSideDoesNotTellWhichZonesTheFramesSaw) {
  // Before the plate the frames saw the middle plates only (0.890 m), past it the outer
  // surfaces (0.900 m): the section is the same, and nothing says so or otherwise.
  SectionSizes sizes;
  for (double w : {0.890, 0.8902}) sizes.record(view(3, w, 1.2));
  for (double w : {0.900, 0.9003}) sizes.record(view(6, w, 1.2));
  EXPECT_TRUE(std::isnan(sizes.change(0, {3}, {6}, kTolerance)));
}

TEST(SectionSizes, OneSizeBeyondAChangeLargerThanAnyZoneIsAChange) {
  // Both zones before the plate (0.890 and 0.900 m), one size past it 30 mm larger than
  // either: the section grew by at least 30 mm whichever zone that is.
  SectionSizes sizes;
  for (double w : {0.890, 0.8902, 0.900, 0.9003}) sizes.record(view(3, w, 1.2));
  for (double w : {0.930, 0.9301}) sizes.record(view(6, w, 1.2));
  EXPECT_NEAR(sizes.change(0, {3}, {6}, kTolerance), 0.030, 0.001);
}

TEST(SectionSizes, ASizeNoSecondViewConfirmsIsNotMeasured) {
  SectionSizes sizes;
  sizes.record(view(3, 0.900, 1.2));
  sizes.record(view(3, 0.890, 1.2));
  sizes.record(view(3, 0.8902, 1.2));
  sizes.record(view(3, 0.9002, 1.2));
  sizes.record(view(6, 0.930, 1.2));
  EXPECT_TRUE(std::isnan(sizes.change(0, {3}, {6}, kTolerance)));
  EXPECT_TRUE(std::isnan(sizes.change(0, {3, 3}, {6, 6}, kTolerance)));  // one view named twice is still one
  EXPECT_TRUE(std::isnan(sizes.change(0, {3}, {9}, kTolerance)));        // a band no frame saw
  // Views of two bands either side count together (the two walls' ties may name different bands).
  sizes.record(view(7, 0.9301, 1.2));
  EXPECT_NEAR(sizes.change(0, {3, 2}, {6, 7}, kTolerance), 0.030, 0.001);
}

}  // namespace
}  // namespace tunnelmap
