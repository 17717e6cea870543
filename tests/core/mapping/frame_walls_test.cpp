// A frame's samples when it found no cross-section of its own: the plate it faces, nothing else.
#include "core/mapping/frame_walls.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/family_girder.h"

namespace tunnelmap {
namespace {

// Girder 15 of the evaluation's family of seed 3 (1.50 m high, plates every 4.78 m, drifted
// walk): frame 62, 0.9 m before a plate, finds no cross-section (the walls beside the plate are
// too short for a zone), yet the plate fills its view, and through its manhole the next one
// shows, 5.7 m away.
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
  EXPECT_TRUE(walls.rims.empty());  // rims are taken where the frame's cross-section places them
}

}  // namespace
}  // namespace tunnelmap
