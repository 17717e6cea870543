// Where a frame finds the rims of the openings in the plates it sees, and how far it reads them:
// the box-girder preset reads depth far enough to see the next plate through a manhole, but
// takes an opening's rim only from views near enough to place it.
#include <gtest/gtest.h>

#include "core/mapping/frame_walls.h"
#include "tests/support/family_girder.h"

namespace tunnelmap {
namespace {

// Girder 5 of the evaluation's family of seed 1: 30.5 m, diaphragms every 3.79 m with
// elliptic manholes, walked through them in stops of about 0.77 m.
TEST(PlateRims, FarPlatesLocaliseButTheirRimsAreLeftToNearerViews) {
  const testing::FamilyGirder girder(1, 5);
  const FrameWallsOptions options;
  long far_plate_points = 0, rim_points = 0;
  for (int i = 0; i < 40; ++i) {
    const FrameResult r = girder.detect(i);
    if (!r.map.detected) continue;
    FrameWalls walls;
    extract_frame_walls(r, walls, options);
    for (const WallSample& s : walls.samples)
      if (s.wall == kTransverseSample && s.point.norm() > options.max_rim_range_m) far_plate_points += s.points;
    for (const RimPoint& p : walls.rims) {
      EXPECT_LE(p.point.norm(), options.max_rim_range_m) << "frame " << i;
      ++rim_points;
    }
  }
  // Plates beyond 5 m, seen through the manhole of the plate before them, are in the frames'
  // samples (they tie the map along the girder); the rims come from the nearer plates.
  EXPECT_GT(far_plate_points, 10000);
  EXPECT_GT(rim_points, 1000);
}

}  // namespace
}  // namespace tunnelmap
