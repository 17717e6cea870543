// A frame's wall samples: the plate it faces when it found no cross-section of its own, and the
// roof of the next section where the roof steps down ahead of it.
#include "core/mapping/frame_walls.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/family_girder.h"

namespace tunnelmap {
namespace {

// Girder 15 of the evaluation's family of seed 3 (1.50 m high, plates every 4.78 m, drifted
// walk): frame 62, 0.9 m before a plate, finds no cross-section (the walls beside the plate are
// too short for a zone), yet the plate fills its view with the rim of its manhole, and through
// the manhole the next one shows, 5.7 m away.
TEST(FrameWalls, AFrameWithoutACrossSectionGivesThePlatesItFaces) {
  const testing::FamilyGirder girder(3, 15);
  const FrameResult r = girder.detect(62);
  ASSERT_FALSE(r.map.detected) << r.map.reason;
  FrameWalls walls;
  extract_frame_walls(r, walls);
  ASSERT_FALSE(walls.samples.empty());
  const Eigen::Isometry3d camera_to_world = girder.sim().pose(62);
  const double spacing = girder.config().diaphragm_spacing_m;
  long near_points = 0, far_points = 0;
  for (const WallSample& s : walls.samples) {
    EXPECT_EQ(s.wall, kTransverseSample);
    // On a plate: the diaphragms stand every `diaphragm_spacing_m` from the girder's start.
    const double x = (camera_to_world * s.point.cast<double>()).x();
    const double from_plate = x - spacing * std::round(x / spacing);
    EXPECT_LT(std::abs(from_plate), 0.03) << "sample at x " << x;
    (s.point.z() < 1.5f ? near_points : far_points) += s.points;
  }
  EXPECT_GT(near_points, 100000);
  EXPECT_GT(far_points, 5000);
  // The rim of the near plate's manhole, on that plate.
  ASSERT_GT(walls.rims.size(), 40u);
  for (const RimPoint& rim : walls.rims) {
    const double x = (camera_to_world * rim.point.cast<double>()).x();
    EXPECT_LT(std::abs(x - spacing * std::round(x / spacing)), 0.03) << "rim point at x " << x;
  }
}

// Girder 14 of the family of seed 10 (0.92 m wide, drifted walk): the roof steps down by 33 mm
// (1.419 to 1.386 m above the floor) at x = 18.604, 2 m past a plate. Frame 40 stands 0.6 m
// before that plate and sees the lower roof through its manhole, 2.6-4 m ahead. It is the only
// kind of frame that sees both roofs: past the plate, the floor is out of view for 1.3 m. The
// lower roof lies 33 mm inside the higher one, deeper than any zone of a wall: unless the frame
// splits its view into two cross-sections there, those samples are "inside", not the roof.
TEST(FrameWalls, ARoofThatStepsDownNearlyThreeMetresAheadIsTheNextSectionsRoof) {
  const testing::FamilyGirder girder(10, 14);
  const double joint_x = 18.604, lower_roof_z = 1.3862;
  const FrameResult r = girder.detect(40);
  ASSERT_TRUE(r.map.detected) << r.map.reason;
  FrameWalls walls;
  extract_frame_walls(r, walls);
  const Eigen::Isometry3d camera_to_world = girder.sim().pose(40);
  ASSERT_NEAR(joint_x - camera_to_world.translation().x(), 2.63, 0.01);
  long lower_roof = 0, off_roof = 0;
  for (const WallSample& s : walls.samples) {
    if (s.wall != static_cast<std::uint8_t>(WallClass::Top) || !s.on_surface) continue;
    const Eigen::Vector3d p = camera_to_world * s.point.cast<double>();
    if (p.x() < joint_x + 0.1) continue;
    (std::abs(p.z() - lower_roof_z) < 0.01 ? lower_roof : off_roof) += s.points;
  }
  EXPECT_GT(lower_roof, 1000);
  EXPECT_LT(off_roof, lower_roof / 20);
}

}  // namespace
}  // namespace tunnelmap
