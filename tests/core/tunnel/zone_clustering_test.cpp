// Zone clustering with anchors: small noisy planes must not chain two plate zones together.
#include <gtest/gtest.h>

#include "core/tunnel/zone_clustering.h"

namespace tunnelmap {
namespace {

// Right wall of simulated field frame 11/0 on the coarse grid: the middle plate (0.5344 m) and
// the edge plates 6 mm further out, with small far planes whose noisy offsets lie in between.
const std::vector<ZonePosition> kRightWall = {{0.5344, 95579}, {0.5403, 2455}, {0.5396, 5678},
                                              {0.5355, 105},   {0.5375, 112},  {0.5338, 71},
                                              {0.5322, 43}};

TEST(ZoneClustering, SmallPlanesDoNotBridgeTwoZones) {
  const auto chained = cluster_zone_positions(kRightWall, 0.004);  // every plane links
  ASSERT_EQ(chained.size(), 1u);

  const auto c = cluster_zone_positions(kRightWall, 0.004, 300);
  ASSERT_EQ(c.size(), 2u);
  // Outer: the two edge plates and the small plane within 4 mm of them (0.5375).
  EXPECT_EQ(c[0].planes, 3);
  EXPECT_EQ(c[0].points, 2455 + 5678 + 112);
  EXPECT_NEAR(c[0].offset_m, (0.5403 * 2455 + 0.5396 * 5678 + 0.5375 * 112) / (2455 + 5678 + 112), 1e-12);
  // Inner: the middle plate with the remaining small planes.
  EXPECT_EQ(c[1].planes, 4);
  EXPECT_EQ(c[1].points, 95579 + 105 + 71 + 43);
  EXPECT_NEAR(c[1].offset_m, 0.5344, 0.0001);
  EXPECT_NEAR(observed_edge_step(c, 300, 0.02), c[0].offset_m - c[1].offset_m, 1e-12);
}

TEST(ZoneClustering, SmallPlanesAwayFromAnchorsClusterAmongThemselves) {
  const auto c = cluster_zone_positions({{0.500, 5000}, {0.530, 100}, {0.533, 120}, {0.560, 50}}, 0.004, 300);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0].offset_m, 0.560, 1e-12);
  EXPECT_EQ(c[1].planes, 2);
  EXPECT_EQ(c[1].points, 220);
  EXPECT_EQ(c[2].points, 5000);
  EXPECT_EQ(outermost_supported_cluster(c, 300), 2);  // small clusters never bound the tunnel
}

TEST(ZoneClustering, ASmallPlaneJoinsTheNearestAnchorCluster) {
  // 0.506 is within 4 mm of both anchor clusters (0.502 and 0.5095): it joins the nearer one.
  const auto c = cluster_zone_positions({{0.502, 1000}, {0.5095, 1000}, {0.5065, 10}}, 0.004, 300);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].planes, 2);  // 0.5095 and 0.5065 (3 mm) rather than 0.502 (4.5 mm)
  EXPECT_EQ(c[1].planes, 1);
}

}  // namespace
}  // namespace tunnelmap
