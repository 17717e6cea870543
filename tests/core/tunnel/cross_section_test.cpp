// A cross-section at a station: the slab's points sit on the fitted rectangle, the rectangle
// has the tunnel's size, right is right looking along the axis, the design rectangle is centred
// on it, and a missing wall is placed from the known size.
#include <gtest/gtest.h>

#include <cmath>

#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "core/tunnel/cross_section.h"
#include "tests/support/synthetic_scene.h"

namespace tunnelmap {
namespace {

// A 0.82 x 1.30 m box tunnel along world +x, the camera on its axis looking down it.
struct BoxTunnel {
  FrameResult result;
  BoxTunnel() {
    const auto room = test::box_room({-1.0, -0.41, -0.65}, {9.0, 0.41, 0.65});
    const auto pose = test::look_at({0, 0, 0}, {1, 0, 0});
    test::SyntheticFrame f = test::render_planes(room, pose, {-1.0, -0.41, -0.65}, {9.0, 0.41, 0.65});
    f.frame.pose = pose;
    Pipeline pipeline;
    pipeline.run(f.frame, result);
  }
};

double distance_to_perimeter(const Eigen::Vector2d& p, const SectionRect& r) {
  return std::min({std::abs(p.x() - r.left), std::abs(p.x() - r.right), std::abs(p.y() - r.bottom),
                   std::abs(p.y() - r.top)});
}

TEST(CrossSection, SlabPointsLieOnTheFittedRectangleOfTheTunnelsSize) {
  const BoxTunnel t;
  ASSERT_TRUE(t.result.map.detected) << t.result.map.reason;
  const CrossSection s = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.05);
  ASSERT_TRUE(s.fitted.has_value());
  EXPECT_NEAR(s.fitted->width(), 0.82, 0.003);
  EXPECT_NEAR(s.fitted->height(), 1.30, 0.003);
  // The camera is on the axis: the rectangle is centred on the section's origin.
  EXPECT_NEAR(s.fitted->left + s.fitted->right, 0.0, 0.005);
  EXPECT_NEAR(s.fitted->bottom + s.fitted->top, 0.0, 0.005);
  ASSERT_GT(s.points.size(), 200u);
  int on = 0;
  for (const SectionPoint& p : s.points) on += distance_to_perimeter(p.at, *s.fitted) < 0.01;
  EXPECT_GT(on, static_cast<int>(0.99 * s.points.size()));
}

TEST(CrossSection, RightIsRightLookingAlongTheAxisAndTheRoofIsUp) {
  const BoxTunnel t;
  const CrossSection s = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.05);
  double right = 0, top = 0;
  int n_right = 0, n_top = 0;
  for (const SectionPoint& p : s.points) {
    if (p.cls == WallClass::Right) right += p.at.x(), ++n_right;
    if (p.cls == WallClass::Top) top += p.at.y(), ++n_top;
  }
  ASSERT_GT(n_right, 20);
  ASSERT_GT(n_top, 20);
  EXPECT_NEAR(right / n_right, 0.41, 0.01);
  EXPECT_NEAR(top / n_top, 0.65, 0.01);
}

TEST(CrossSection, TheSlabKeepsOnlyPointsNearTheStation) {
  const BoxTunnel t;
  const CrossSection thin = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.01);
  const CrossSection thick = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.10);
  EXPECT_GT(thick.points.size(), 5 * thin.points.size());
  const CrossSection capped = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.10,
                                            std::nullopt, std::nullopt, 100);
  EXPECT_EQ(capped.points.size(), 100u);
  // The stations the frame sees start beyond the near range and end within the max range.
  const StationRange r = visible_stations(t.result.map);
  EXPECT_GT(r.to_m, 3.0);
  EXPECT_LE(r.to_m, 5.01);
  EXPECT_LT(r.from_m, r.to_m);
}

TEST(CrossSection, TheDesignRectangleIsCentredOnTheFittedOne) {
  const BoxTunnel t;
  const CrossSection s = cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.05, 0.80, 1.28);
  ASSERT_TRUE(s.design.has_value());
  EXPECT_NEAR(s.design->width(), 0.80, 1e-12);
  EXPECT_NEAR(s.design->height(), 1.28, 1e-12);
  EXPECT_NEAR(s.design->left - s.fitted->left, 0.01, 0.003);  // 10 mm narrower on each side
  EXPECT_FALSE(cross_section(t.result.cloud, t.result.planes, t.result.map, 2.0, 0.05, 0.80).design);
}

TEST(CrossSection, AMissingWallIsPlacedFromTheKnownSize) {
  const BoxTunnel t;
  TunnelMap map = t.result.map;
  map.wall(WallClass::Top).found = false;
  const CrossSection s = cross_section(t.result.cloud, t.result.planes, map, 2.0, 0.05);
  ASSERT_TRUE(s.fitted.has_value());
  EXPECT_NEAR(s.fitted->height(), map.height_m, 1e-9);
  EXPECT_EQ(s.no_fit_reason, "");
  // Without the height the rectangle cannot be drawn, and the section says why: the tunnel
  // was found, the floor was seen, the height was not known.
  map.height_source = DimensionSource::Unseen;
  const CrossSection no_height = cross_section(t.result.cloud, t.result.planes, map, 2.0, 0.05);
  EXPECT_FALSE(no_height.fitted.has_value());
  EXPECT_EQ(no_height.no_fit_reason, "the roof not seen and the height unknown");
  // A size known (from context) does not place a pair of walls neither of which was seen.
  map.height_source = DimensionSource::Context;
  map.wall(WallClass::Bottom).found = false;
  const CrossSection no_ends = cross_section(t.result.cloud, t.result.planes, map, 2.0, 0.05);
  EXPECT_FALSE(no_ends.fitted.has_value());
  EXPECT_EQ(no_ends.no_fit_reason, "neither floor nor roof seen");
  map.detected = false;
  const CrossSection none = cross_section(t.result.cloud, t.result.planes, map, 2.0, 0.05);
  EXPECT_FALSE(none.fitted.has_value());
  EXPECT_EQ(none.no_fit_reason, "tunnel not detected");
}

// A frame that sees a change of section: 0.84 x 1.30 m up to x = 3 m, then 0.78 x 1.26 m. The
// frame's fitted rectangle is one size for the whole frame; each cut measures its own walls.
TEST(CrossSection, TheCutMeasuresItsOwnWallsAcrossAChangeOfSection) {
  const Eigen::Vector3d near_lo{-1.0, -0.42, -0.65}, near_hi{3.0, 0.42, 0.65};
  const Eigen::Vector3d far_lo{3.0, -0.39, -0.63}, far_hi{9.0, 0.39, 0.63};
  const auto pose = test::look_at({0, 0, 0}, {1, 0, 0});
  // Open where the two meet: no end wall at x = 3 m (box_room's planes are -x, +x, -y, +y, -z, +z).
  auto near_walls = test::box_room(near_lo, near_hi), far_walls = test::box_room(far_lo, far_hi);
  near_walls.erase(near_walls.begin() + 1);
  far_walls.erase(far_walls.begin());
  test::SyntheticFrame near = test::render_planes(near_walls, pose, near_lo, near_hi);
  const test::SyntheticFrame far = test::render_planes(far_walls, pose, far_lo, far_hi);
  for (std::size_t i = 0; i < near.frame.depth.size(); ++i) {  // the nearer surface of the two
    const float a = near.frame.depth[i], b = far.frame.depth[i];
    if (a <= 0.0f || (b > 0.0f && b < a)) near.frame.depth[i] = b;
  }
  near.frame.pose = pose;
  FrameResult result;
  Pipeline pipeline;
  pipeline.run(near.frame, result);
  ASSERT_TRUE(result.map.detected) << result.map.reason;
  const CrossSection before = cross_section(result.cloud, result.planes, result.map, 1.5, 0.05);
  const CrossSection after = cross_section(result.cloud, result.planes, result.map, 5.0, 0.1);
  ASSERT_TRUE(before.cut_width_m && before.cut_height_m);
  ASSERT_TRUE(after.cut_width_m && after.cut_height_m);
  EXPECT_NEAR(*before.cut_width_m, 0.84, 0.005);
  EXPECT_NEAR(*before.cut_height_m, 1.30, 0.005);
  EXPECT_NEAR(*after.cut_width_m, 0.78, 0.005);
  EXPECT_NEAR(*after.cut_height_m, 1.26, 0.005);
  // One of the two cuts is not the frame's size: the fitted rectangle cannot stand for both.
  ASSERT_TRUE(before.fitted.has_value());
  EXPECT_GT(std::max(std::abs(before.fitted->width() - 0.84), std::abs(before.fitted->width() - 0.78)), 0.02);
}

// The field preset's girder (0.84 x 1.20 m): each wall a middle plate 7.5 mm inside its edge
// bands. Near the camera the cut measures the walls' outer surface, as the frame's rectangle and
// the map do (the median of all the wall's points lay on the middle plates, 15 mm narrow). At 2 m
// one side wall's edge band breaks into planes too small to count, and the cut, measured in the
// slab alone, keeps that wall's middle plate: within a plate's thickness.
TEST(CrossSection, TheCutOfAZonedWallIsItsOuterSurface) {
  SimConfig config = SimConfig::from_preset("field");
  config.frames = 1;
  const TunnelSimulator sim(config);
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/field.json");
  Pipeline pipeline(params);
  const FrameResult r = pipeline.run(sim.render(0).frame);
  ASSERT_TRUE(r.map.detected) << r.map.reason;
  const auto cut_at = [&](double station) {
    return cross_section(r.cloud, r.planes, r.map, station, 0.025, std::nullopt, std::nullopt, 20000,
                         mm_to_m(params.get(tunnel_keys::zone_cluster_mm)));
  };
  for (const double station : {1.2, 1.5}) {
    const CrossSection s = cut_at(station);
    ASSERT_TRUE(s.fitted && s.cut_width_m) << station;
    EXPECT_NEAR(*s.cut_width_m, config.width_m, 0.003) << station;
    EXPECT_NEAR(*s.cut_width_m, s.fitted->width(), 0.003) << station;
  }
  const CrossSection far = cut_at(2.0);
  ASSERT_TRUE(far.cut_width_m);
  EXPECT_NEAR(*far.cut_width_m, config.width_m, 0.0075);
}

TEST(CrossSection, ACutWithoutAWallHasNoSizeThere) {
  const BoxTunnel t;
  const CrossSection beyond = cross_section(t.result.cloud, t.result.planes, t.result.map, 30.0, 0.05);
  EXPECT_FALSE(beyond.cut_width_m.has_value());
  EXPECT_FALSE(beyond.cut_height_m.has_value());
}

}  // namespace
}  // namespace tunnelmap
