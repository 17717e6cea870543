// A compartment seen through a manhole from just before its plate: the opening hides the walls'
// edge bands beyond it, and the frame sees only their middle plates. Which zone a lone plane
// is, a frame that saw no edge band of its own cannot tell; the walls' layers are the same
// along the girder, so the step the earlier frames saw is the wall's.
#include <gtest/gtest.h>

#include <string>

#include "core/evaluation/girder_family.h"
#include "core/sim/sim_config.h"
#include "tests/support/mapped_girder.h"

namespace tunnelmap {
namespace {

// Girder 16 of the evaluation's family of seed 2: 32.5 m, 0.816 x 1.438 m, diaphragms every
// 3.04 m and the preset's manhole plate at 5 m, 1.08 m before the second diaphragm, walked
// through the openings in 0.527 m stops with drifting poses. Shortened, its frames no longer
// show the case (the rivets and the noise are drawn along the whole girder).
SimConfig girder_with_a_short_compartment() { return draw_girders(17, 2)[16].config; }

TEST(ThroughOpening, AWallSeenOnlyThroughAManholeIsMeasuredToItsOuterSurface) {
  const SimConfig c = girder_with_a_short_compartment();
  const StationMap map = testing::map_simulated_girder(c);
  ASSERT_TRUE(map.ok) << map.reason;
  int short_compartment = 0;
  for (const Station& s : map.stations) {
    if (s.width_source != DimensionSource::Measured) continue;
    SCOPED_TRACE("station " + std::to_string(s.station_m));
    // Both walls' middle plates taken for the walls made these 16 mm narrow (10 + 6 mm plates).
    EXPECT_NEAR(s.width_m, c.width_m, 0.008);
    const double x = s.station_m + c.walk->start_x_m;
    if (x > 5.1 && x < 6.0) ++short_compartment;
  }
  EXPECT_GE(short_compartment, 5);
}

}  // namespace
}  // namespace tunnelmap
