// Coarse-to-fine refinement: every full-resolution pixel joins the nearby grown plane whose final
// model it passes (eq. 2), statistics come from the full-resolution members, small planes are
// dropped and the rest renumbered, and the edge-on pass's pixel states are classified.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/planes/grazing_growth.h"
#include "core/planes/plane_growing.h"
#include "core/planes/plane_refinement.h"
#include "core/planes/plane_slots.h"
#include "tests/core/planes/hand_cloud.h"

namespace tunnelmap {
namespace {

using testing::hand_cloud;
using testing::no_normal;
using testing::tilted;

constexpr float kPitch = 0.01f;
const Eigen::Vector3f kFacing(0, 0, -1);

struct GridPlane {
  Eigen::Vector3d mean_normal, centroid;
};

// The grid's result as the grower leaves it: `labels` (cw x ch) and one plane per entry of
// `models`, with ids 1, 2, ...
PlaneSegments grid(int cw, int ch, std::vector<std::int32_t> labels, const std::vector<GridPlane>& models) {
  PlaneSegments s;
  s.width = cw, s.height = ch;
  s.labels = std::move(labels);
  for (std::size_t i = 0; i < models.size(); ++i) {
    s.planes.emplace_back();
    s.planes.back().id = static_cast<int>(i) + 1;
    s.planes.back().mean_normal = models[i].mean_normal;
    s.planes.back().centroid = models[i].centroid;
  }
  return s;
}

void refine(const OrganizedCloud& full, int step, const GrowOptions& options, PlaneSegments& planes,
            std::vector<std::int32_t>& coarse, std::vector<std::uint8_t>* states = nullptr) {
  RefinementScratch scratch;
  ContourBufferPool pool;
  refine_to_full_resolution(full, step, options, planes, coarse, states, scratch, pool);
}

GrowOptions small_plane_options() {
  GrowOptions o;
  o.min_points = 3;
  o.min_area_m2 = 0.0;
  return o;
}

TEST(PlaneRefinement, SubsampleTakesEveryStepthPixelAndScalesIntrinsics) {
  const OrganizedCloud full = hand_cloud(5, 3, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(static_cast<float>(u), static_cast<float>(v), 1.0f), n = kFacing;
  });
  OrganizedCloud coarse;
  subsample_cloud(full, 2, coarse);
  ASSERT_EQ(coarse.width, 3);
  ASSERT_EQ(coarse.height, 2);
  EXPECT_EQ(coarse.points[coarse.index(2, 1)], Eigen::Vector3f(4, 2, 1));  // full pixel (4, 2)
  EXPECT_EQ(coarse.points[coarse.index(1, 0)], Eigen::Vector3f(2, 0, 1));
  EXPECT_DOUBLE_EQ(coarse.intrinsics.fx, 570.3 / 2);
  EXPECT_DOUBLE_EQ(coarse.intrinsics.cy, 239.5 / 2);
  EXPECT_EQ(coarse.intrinsics.width, 3);
}

TEST(PlaneRefinement, EveryPixelPassingTheFinalModelJoinsItsPlane) {
  // The plane z = 1 m, 20 x 20 pixels, grown on the step-2 grid (10 x 10 samples, all plane 1).
  // Three pixels must stay out: 30 mm off the plane (epsilon 15 mm), no normal, normal 10 deg off
  // (lambda 4 deg). The other 397, on the grid or between its samples, join.
  const OrganizedCloud full = hand_cloud(20, 20, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f), n = kFacing;
    if (u == 5 && v == 5) p.z() = 0.97f;
    if (u == 7 && v == 7) n = no_normal();
    if (u == 9 && v == 3) n = tilted(kFacing, 10.0);
  });
  PlaneSegments planes = grid(10, 10, std::vector<std::int32_t>(100, 1), {{{0, 0, -1}, {0.1, 0.1, 1.0}}});
  std::vector<std::int32_t> coarse;
  GrowOptions opt;
  opt.min_area_m2 = 0.001;
  refine(full, 2, opt, planes, coarse);
  ASSERT_EQ(planes.width, 20);
  ASSERT_EQ(planes.labels.size(), 400u);
  EXPECT_EQ(coarse, std::vector<std::int32_t>(100, 1));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int joined = 0;
  for (int v = 0; v < 20; ++v)
    for (int u = 0; u < 20; ++u) {
      const bool out = (u == 5 && v == 5) || (u == 7 && v == 7) || (u == 9 && v == 3);
      ASSERT_EQ(planes.labels[v * 20 + u], out ? 0 : 1) << u << "," << v;
      if (!out) sum += full.points[full.index(u, v)].cast<double>(), ++joined;
    }
  ASSERT_EQ(planes.planes.size(), 1u);
  const PlaneSegment& p = planes.planes[0];
  EXPECT_EQ(p.points, 397);
  EXPECT_LT((p.centroid - sum / joined).norm(), 1e-9);
  EXPECT_LT((p.normal - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  EXPECT_NEAR(p.offset_m, 1.0, 1e-9);
  EXPECT_NEAR(p.rms_m, 0.0, 1e-6);
  // Pixel footprint z^3 / (fx fy |offset|) = 1 / 570.3^2 m^2 each.
  EXPECT_NEAR(p.area_m2, 397.0 / (570.3 * 570.3), 1e-12);
  EXPECT_EQ(p.bbox_u0, 0);
  EXPECT_EQ(p.bbox_v1, 19);
}

TEST(PlaneRefinement, WherePlanesMeetTheClosestPassingPlaneWins) {
  // Two zone plates 5 mm apart: columns 0..3 at z = 1.000 (plane 1), 4..7 at z = 1.005 (plane 2).
  // Column 3 lies between grid columns 1 (plane 1) and 2 (plane 2) and passes both; its row-0
  // pixel sits at 1.004 (1 mm from plane 2), its row-1 pixel at 1.001 (1 mm from plane 1).
  const OrganizedCloud full = hand_cloud(8, 4, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    float z = u < 4 ? 1.0f : 1.005f;
    if (u == 3 && v == 0) z = 1.004f;
    if (u == 3 && v == 1) z = 1.001f;
    p = Eigen::Vector3f(u * kPitch, v * kPitch, z), n = kFacing;
  });
  PlaneSegments planes = grid(4, 2, {1, 1, 2, 2, 1, 1, 2, 2}, {{{0, 0, -1}, {0, 0, 1.0}}, {{0, 0, -1}, {0, 0, 1.005}}});
  std::vector<std::int32_t> coarse;
  refine(full, 2, small_plane_options(), planes, coarse);
  const std::vector<std::int32_t> row0(planes.labels.begin(), planes.labels.begin() + 8);
  const std::vector<std::int32_t> row1(planes.labels.begin() + 8, planes.labels.begin() + 16);
  EXPECT_EQ(row0, (std::vector<std::int32_t>{1, 1, 1, 2, 2, 2, 2, 2}));
  EXPECT_EQ(row1, (std::vector<std::int32_t>{1, 1, 1, 1, 2, 2, 2, 2}));
  ASSERT_EQ(planes.planes.size(), 2u);
  EXPECT_EQ(planes.planes[0].points, 15);  // columns 0..2 (12) and column 3 in rows 1..3
  EXPECT_EQ(planes.planes[1].points, 17);
}

TEST(PlaneRefinement, PlaneBelowMinPointsAtFullResolutionIsDroppedAndTheRestRenumbered) {
  // A 2 x 2 patch 100 mm in front of the background (one grid sample, plane 1) and the
  // background (plane 2). At full resolution plane 1 has 4 points, below min_points 10.
  const OrganizedCloud full = hand_cloud(20, 10, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, u < 2 && v < 2 ? 0.9f : 1.0f), n = kFacing;
  });
  std::vector<std::int32_t> grid_labels(50, 2);
  grid_labels[0] = 1;
  PlaneSegments planes = grid(10, 5, grid_labels, {{{0, 0, -1}, {0, 0, 0.9}}, {{0, 0, -1}, {0.1, 0.05, 1.0}}});
  std::vector<std::int32_t> coarse;
  std::vector<std::uint8_t> states;
  GrowOptions opt = small_plane_options();
  opt.min_points = 10;
  refine(full, 2, opt, planes, coarse, &states);
  ASSERT_EQ(planes.planes.size(), 1u);
  EXPECT_EQ(planes.planes[0].id, 1);
  EXPECT_EQ(planes.planes[0].points, 196);
  for (int v = 0; v < 10; ++v)
    for (int u = 0; u < 20; ++u) ASSERT_EQ(planes.labels[v * 20 + u], u < 2 && v < 2 ? 0 : 1) << u << "," << v;
  EXPECT_EQ(coarse[0], 0);
  EXPECT_EQ(coarse[1], 1);
  // The dropped plane's pixels are free for the edge-on pass again (a surface facing the camera
  // at 0.9 m: joinable, not a seed); the kept plane's are taken.
  ASSERT_EQ(states.size(), 200u);
  EXPECT_EQ(states[0], kEdgeOnJoinable);
  EXPECT_EQ(states[21], kEdgeOnJoinable);
  EXPECT_EQ(states[5 * 20 + 5], kEdgeOnTaken);
}

TEST(PlaneRefinement, UnlabelledPixelsAreClassifiedForTheEdgeOnPass) {
  // No plane on the grid. Pixel 0: no normal (taken). Pixel 1: facing the camera at 1 m
  // (grid neighbours 20 mm apart: joinable). Pixel 2: a floor 0.1 m below the camera seen from
  // 2 m, |n.p| = 0.1: step r^2 = 8.0 > c f |n.p| = 0.04 * 570.3 * 0.1 = 2.28, a seed.
  const OrganizedCloud full = hand_cloud(4, 2, [](int u, int, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    if (u == 1) p = Eigen::Vector3f(0, 0, 1), n = kFacing;
    if (u >= 2) p = Eigen::Vector3f(0, 0.1f, 2.0f), n = Eigen::Vector3f(0, -1, 0);
  });
  PlaneSegments planes = grid(2, 1, {0, 0}, {});
  std::vector<std::int32_t> coarse;
  std::vector<std::uint8_t> states;
  refine(full, 2, small_plane_options(), planes, coarse, &states);
  EXPECT_TRUE(planes.planes.empty());
  EXPECT_EQ(planes.labels, std::vector<std::int32_t>(8, 0));
  EXPECT_EQ(states, (std::vector<std::uint8_t>{kEdgeOnTaken, kEdgeOnJoinable, kEdgeOnSeed, kEdgeOnSeed,
                                               kEdgeOnTaken, kEdgeOnJoinable, kEdgeOnSeed, kEdgeOnSeed}));
}

}  // namespace
}  // namespace tunnelmap
