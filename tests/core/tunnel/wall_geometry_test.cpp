// Wall geometry: the centre line, each wall's rectangle over the visible extent and its zones
// (forbidden bands along the corners, traversable middle plate) for a known cross-section.
#include <gtest/gtest.h>

#include <array>
#include <utility>

#include <Eigen/Geometry>

#include "core/tunnel/wall_geometry.h"

namespace tunnelmap {
namespace {

// Camera frame: right +x, up -y, axis +z (the default TemplateFrame). Walls at x = -0.4 (left)
// and x = 0.5 (right), roof at y = -0.6, floor at y = 0.7: 0.9 m wide, 1.3 m high; seen from
// z = 1 to z = 3 m.
const WallOffsets kOffsets{0.4, 0.5, 0.6, 0.7};

TemplateFrame level_frame() {
  TemplateFrame t;
  t.ok = true;
  return t;
}

TunnelMap built(double band) {
  TunnelMap map;
  build_wall_geometry(level_frame(), kOffsets, 1.0, 3.0, band, map);
  return map;
}

double side(const std::array<Eigen::Vector3d, 4>& c, int i) { return (c[(i + 1) % 4] - c[i]).norm(); }

TEST(WallGeometry, CentreLineAndExtentOfAKnownCrossSection) {
  const TunnelMap map = built(0.1);
  // Centre of x in [-0.4, 0.5], y in [-0.6, 0.7], at the near end of the extent.
  EXPECT_LT((map.axis_point - Eigen::Vector3d(0.05, 0.05, 1.0)).norm(), 1e-12);
  EXPECT_LT((map.axis_dir - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);
  EXPECT_LT((map.up - Eigen::Vector3d(0, -1, 0)).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(map.extent_min_m, 0.0);
  EXPECT_DOUBLE_EQ(map.extent_max_m, 2.0);
}

TEST(WallGeometry, EachWallRectangleLiesOnItsPlaneAndSpansTheCrossSection) {
  const TunnelMap map = built(0.1);
  struct Expect { WallClass cls; Eigen::Vector3d n; double offset, span; };
  const Expect walls[] = {{WallClass::Left, {1, 0, 0}, 0.4, 1.3},
                          {WallClass::Right, {-1, 0, 0}, 0.5, 1.3},
                          {WallClass::Top, {0, 1, 0}, 0.6, 0.9},
                          {WallClass::Bottom, {0, -1, 0}, 0.7, 0.9}};
  for (const Expect& e : walls) {
    const Wall& w = map.wall(e.cls);
    SCOPED_TRACE(wall_class_name(e.cls));
    EXPECT_LT((w.normal - e.n).norm(), 1e-12);
    EXPECT_DOUBLE_EQ(w.offset_m, e.offset);
    for (const Eigen::Vector3d& c : w.boundary) EXPECT_NEAR(w.normal.dot(c) + w.offset_m, 0.0, 1e-12);
    EXPECT_NEAR(side(w.boundary, 0), 2.0, 1e-12);  // along the axis
    EXPECT_NEAR(side(w.boundary, 1), e.span, 1e-12);
    EXPECT_NEAR(side(w.boundary, 2), 2.0, 1e-12);
    EXPECT_NEAR(side(w.boundary, 3), e.span, 1e-12);
    // Counter-clockwise seen from inside: the corners' right-hand normal is the inward normal.
    const Eigen::Vector3d turn = (w.boundary[1] - w.boundary[0]).cross(w.boundary[2] - w.boundary[1]);
    EXPECT_NEAR(turn.normalized().dot(w.normal), 1.0, 1e-12);
  }
}

TEST(WallGeometry, ZonesAreCornerBandsAroundAMiddlePlate) {
  // Band 0.1 m: left wall 0.1 + 1.1 + 0.1 across its 1.3 m, roof 0.1 + 0.7 + 0.1 across 0.9 m.
  const TunnelMap map = built(0.1);
  for (const auto& [cls, middle] : {std::pair{WallClass::Left, 1.1}, std::pair{WallClass::Top, 0.7}}) {
    const Wall& w = map.wall(cls);
    SCOPED_TRACE(wall_class_name(cls));
    ASSERT_EQ(w.zones.size(), 3u);
    EXPECT_EQ(w.zones[0].kind, ZoneKind::Forbidden);
    EXPECT_EQ(w.zones[1].kind, ZoneKind::Traversable);
    EXPECT_EQ(w.zones[2].kind, ZoneKind::Forbidden);
    EXPECT_NEAR(side(w.zones[0].corners, 1), 0.1, 1e-12);
    EXPECT_NEAR(side(w.zones[1].corners, 1), middle, 1e-12);
    EXPECT_NEAR(side(w.zones[2].corners, 1), 0.1, 1e-12);
    // The bands tile the wall: each starts where the previous one ends.
    EXPECT_LT((w.zones[0].corners[0] - w.boundary[0]).norm(), 1e-12);
    EXPECT_LT((w.zones[1].corners[0] - w.zones[0].corners[3]).norm(), 1e-12);
    EXPECT_LT((w.zones[2].corners[0] - w.zones[1].corners[3]).norm(), 1e-12);
    EXPECT_LT((w.zones[2].corners[3] - w.boundary[3]).norm(), 1e-12);
  }
  // The left wall's first band is the one along the floor (y from 0.7 up to 0.6).
  for (const Eigen::Vector3d& c : map.wall(WallClass::Left).zones[0].corners) {
    EXPECT_NEAR(c.x(), -0.4, 1e-12);
    EXPECT_GE(c.y(), 0.6 - 1e-12);
    EXPECT_LE(c.y(), 0.7 + 1e-12);
  }
}

TEST(WallGeometry, WallNoWiderThanTwoBandsIsAllForbidden) {
  // Band 0.5 m: roof and floor (0.9 m <= 1.0) are one forbidden zone; the walls (1.3 m) keep a
  // 0.3 m middle plate.
  const TunnelMap map = built(0.5);
  const Wall& top = map.wall(WallClass::Top);
  ASSERT_EQ(top.zones.size(), 1u);
  EXPECT_EQ(top.zones[0].kind, ZoneKind::Forbidden);
  for (int i = 0; i < 4; ++i) EXPECT_LT((top.zones[0].corners[i] - top.boundary[i]).norm(), 1e-12);
  const Wall& right = map.wall(WallClass::Right);
  ASSERT_EQ(right.zones.size(), 3u);
  EXPECT_NEAR(side(right.zones[1].corners, 1), 0.3, 1e-12);
}

TEST(WallGeometry, WallRectangleBandIsMeasuredFromTheLowEdgeWhateverTheEdgeOrder) {
  // The floor (inward normal -y), from x = 0.5 to x = -0.4: across = n x axis = -x, so x = 0.5 is
  // the low edge; the band 0.2..0.5 m from it spans x = 0.3 .. 0.0.
  const Eigen::Vector3d n(0, -1, 0), axis(0, 0, 1), a(0.5, 0.7, 0), b(-0.4, 0.7, 0);
  const std::array<Eigen::Vector3d, 4> expected = {Eigen::Vector3d(0.3, 0.7, 1), Eigen::Vector3d(0.3, 0.7, 3),
                                                   Eigen::Vector3d(0.0, 0.7, 3), Eigen::Vector3d(0.0, 0.7, 1)};
  for (const auto& r : {wall_rectangle(n, axis, a, b, 1.0, 3.0, 0.2, 0.5), wall_rectangle(n, axis, b, a, 1.0, 3.0, 0.2, 0.5)})
    for (int i = 0; i < 4; ++i) EXPECT_LT((r[i] - expected[i]).norm(), 1e-12) << i;
}

TEST(WallGeometry, RebuildFromTheMapRepeatsTheGeometryAndClearsUnfoundWalls) {
  TunnelMap map = built(0.1);
  const TunnelMap original = map;
  for (Wall& w : map.walls) w.found = true;
  map.wall(WallClass::Right).found = false;
  rebuild_wall_geometry(map, 0.1);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 4; ++i) EXPECT_LT((map.walls[k].boundary[i] - original.walls[k].boundary[i]).norm(), 1e-12);
  EXPECT_LT((map.axis_point - original.axis_point).norm(), 1e-12);
  EXPECT_EQ(map.wall(WallClass::Left).zones.size(), 3u);
  EXPECT_TRUE(map.wall(WallClass::Right).zones.empty());
  // The roof inferred 0.2 m higher: the side walls grow to 1.5 m and the centre rises 0.1 m.
  map.wall(WallClass::Top).offset_m = 0.8;
  rebuild_wall_geometry(map, 0.1);
  EXPECT_NEAR(side(map.wall(WallClass::Left).boundary, 1), 1.5, 1e-12);
  EXPECT_LT((map.axis_point - Eigen::Vector3d(0.05, -0.05, 1.0)).norm(), 1e-12);
}

}  // namespace
}  // namespace tunnelmap
