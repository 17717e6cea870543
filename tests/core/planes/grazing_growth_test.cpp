// The edge-on pass of coarse-to-fine growing: every-pixel growing seeded only where the grid
// cannot connect a surface, joining only pixels no plane took, adding planes of at least the
// minimum size with the next ids.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/planes/grazing_growth.h"
#include "core/planes/plane_growing.h"
#include "core/planes/plane_refinement.h"
#include "core/planes/plane_slots.h"
#include "core/planes/region_grower.h"
#include "tests/core/planes/hand_cloud.h"

namespace tunnelmap {
namespace {

using testing::hand_cloud;

constexpr float kPitch = 0.01f;
const Eigen::Vector3f kFacing(0, 0, -1);
constexpr int kW = 20, kH = 12;

// The plane z = 1 m, 20 x 12 pixels.
OrganizedCloud flat_plane() {
  return hand_cloud(kW, kH, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f), n = kFacing;
  });
}

// After refinement: plane 1 holds columns 0..9 (taken); `state(u, v)` gives the other pixels'.
template <class State>
PlaneSegments after_refinement(std::vector<std::uint8_t>& states, State state) {
  PlaneSegments planes;
  planes.width = kW, planes.height = kH;
  planes.planes.emplace_back();
  planes.planes[0].id = 1;
  planes.labels.assign(kW * kH, 0);
  states.assign(kW * kH, kEdgeOnTaken);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) {
      if (u < 10) planes.labels[v * kW + u] = 1;
      else states[v * kW + u] = state(u, v);
    }
  return planes;
}

int edge_on_pass(const OrganizedCloud& full, const GrowOptions& options, PlaneSegments& planes,
                 const std::vector<std::uint8_t>& states) {
  RegionGrower grower;
  ContourBufferPool pool;
  return grow_edge_on_surfaces(full, options, planes, states, grower, pool);
}

GrowOptions no_area_limit() {
  GrowOptions o;
  o.min_area_m2 = 0.0;
  return o;
}

TEST(GrazingGrowth, GridCannotConnectBeyondTheIncidenceWhereSamplesOutrunTheCandidateDistance) {
  // From 2 m with step 2, f = 570.3 px, c = 40 mm: grid neighbours lie 2 r / (f cos theta) apart,
  // beyond 40 mm once cos theta < 2 * 2 / (570.3 * 0.04) = 0.17535, i.e. theta > 79.90 deg.
  const Eigen::Vector3f p(0, 0, 2);
  const auto normal_at = [](double deg) {
    const float t = static_cast<float>(deg * M_PI / 180.0);
    return Eigen::Vector3f(0, -std::sin(t), -std::cos(t));
  };
  EXPECT_TRUE(grid_cannot_connect(p, normal_at(80.0), 2, 570.3f, 0.04f));
  EXPECT_FALSE(grid_cannot_connect(p, normal_at(79.8), 2, 570.3f, 0.04f));
  // Every pixel (step 1) connects the same surface: 1 r / (f cos theta) = 20 mm.
  EXPECT_FALSE(grid_cannot_connect(p, normal_at(80.0), 1, 570.3f, 0.04f));
}

TEST(GrazingGrowth, SeededRegionJoinsFreePixelsButNeverTakenOnes) {
  // Columns 10..19: rows 0..5 seeds, rows 6..11 joinable, all on the plane that also holds the
  // taken columns 0..9. The new plane gets the 120 free pixels and id 2; plane 1 keeps its own.
  std::vector<std::uint8_t> states;
  PlaneSegments planes = after_refinement(states, [](int, int v) { return v < 6 ? kEdgeOnSeed : kEdgeOnJoinable; });
  ASSERT_EQ(edge_on_pass(flat_plane(), no_area_limit(), planes, states), 1);
  ASSERT_EQ(planes.planes.size(), 2u);
  const PlaneSegment& p = planes.planes[1];
  EXPECT_EQ(p.id, 2);
  EXPECT_TRUE(p.edge_on);
  EXPECT_EQ(p.points, 120);
  EXPECT_EQ(p.bbox_u0, 10);
  EXPECT_EQ(p.bbox_u1, 19);
  EXPECT_EQ(p.bbox_v0, 0);
  EXPECT_EQ(p.bbox_v1, 11);
  EXPECT_NEAR(p.centroid.x(), 0.145, 1e-6);
  EXPECT_LT((p.normal - Eigen::Vector3d(0, 0, -1)).norm(), 1e-6);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) ASSERT_EQ(planes.labels[v * kW + u], u < 10 ? 1 : 2) << u << "," << v;
}

TEST(GrazingGrowth, JoinablePixelsAloneSeedNothing) {
  std::vector<std::uint8_t> states;
  PlaneSegments planes = after_refinement(states, [](int, int) { return kEdgeOnJoinable; });
  EXPECT_EQ(edge_on_pass(flat_plane(), no_area_limit(), planes, states), 0);
  EXPECT_EQ(planes.planes.size(), 1u);
  for (int i = 0; i < kW * kH; ++i) ASSERT_EQ(planes.labels[i], i % kW < 10 ? 1 : 0);
}

TEST(GrazingGrowth, RegionBelowMinPointsIsNotAdded) {
  // A 6 x 7 = 42 pixel seed block (columns 12..17, rows 2..8), the rest taken.
  std::vector<std::uint8_t> states;
  PlaneSegments planes = after_refinement(states, [](int u, int v) {
    return u >= 12 && u < 18 && v >= 2 && v < 9 ? kEdgeOnSeed : kEdgeOnTaken;
  });
  GrowOptions opt = no_area_limit();
  opt.min_points = 43;
  EXPECT_EQ(edge_on_pass(flat_plane(), opt, planes, states), 0);
  EXPECT_EQ(planes.planes.size(), 1u);
  EXPECT_EQ(planes.labels[5 * kW + 14], 0);
  opt.min_points = 42;
  ASSERT_EQ(edge_on_pass(flat_plane(), opt, planes, states), 1);
  EXPECT_EQ(planes.planes[1].points, 42);
  EXPECT_EQ(planes.labels[5 * kW + 14], 2);
}

TEST(GrazingGrowth, RegionBelowMinAreaIsNotAdded) {
  // 60 seed pixels at 1 m facing the camera: 60 / 570.3^2 = 1.845e-4 m^2.
  std::vector<std::uint8_t> states;
  PlaneSegments planes = after_refinement(states, [](int, int v) { return v < 6 ? kEdgeOnSeed : kEdgeOnTaken; });
  GrowOptions opt;
  opt.min_area_m2 = 2.0e-4;
  EXPECT_EQ(edge_on_pass(flat_plane(), opt, planes, states), 0);
  EXPECT_EQ(planes.planes.size(), 1u);  // the statistics slot tried for it is given back
  opt.min_area_m2 = 1.7e-4;
  ASSERT_EQ(edge_on_pass(flat_plane(), opt, planes, states), 1);
  EXPECT_NEAR(planes.planes[1].area_m2, 60.0 / (570.3 * 570.3), 1e-12);
}

TEST(GrazingGrowth, FloorSeenEdgeOnIsGrownFromTheRefinementStates) {
  // A floor 0.1 m below the camera, 1.5 to 1.775 m away: rows 25 mm apart, so the step-2 grid's
  // rows are 50 mm apart, beyond the 40 mm candidate distance, and no grid plane holds it.
  // Refinement marks every pixel a seed (step r^2 >= 4.5 > c f |n.p| = 2.28); every-pixel
  // growing then connects all 240 (diagonal neighbours 27 mm apart).
  const OrganizedCloud full = hand_cloud(kW, kH, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch - 0.1f, 0.1f, 1.5f + 0.025f * v), n = Eigen::Vector3f(0, -1, 0);
  });
  PlaneSegments planes;
  planes.width = kW / 2, planes.height = kH / 2;
  planes.labels.assign(planes.width * planes.height, 0);
  std::vector<std::int32_t> coarse;
  std::vector<std::uint8_t> states;
  RefinementScratch scratch;
  ContourBufferPool pool;
  const GrowOptions opt;
  refine_to_full_resolution(full, 2, opt, planes, coarse, &states, scratch, pool);
  ASSERT_EQ(states, std::vector<std::uint8_t>(kW * kH, kEdgeOnSeed));
  ASSERT_EQ(edge_on_pass(full, opt, planes, states), 1);
  ASSERT_EQ(planes.planes.size(), 1u);
  const PlaneSegment& p = planes.planes[0];
  EXPECT_EQ(p.id, 1);
  EXPECT_TRUE(p.edge_on);
  EXPECT_EQ(p.points, kW * kH);
  EXPECT_LT((p.normal - Eigen::Vector3d(0, -1, 0)).norm(), 1e-6);
  EXPECT_NEAR(p.offset_m, 0.1, 1e-6);
  EXPECT_EQ(planes.labels, std::vector<std::int32_t>(kW * kH, 1));
}

}  // namespace
}  // namespace tunnelmap
