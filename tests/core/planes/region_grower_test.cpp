// RegionGrower: the PG&C growing loop (eq. 2 distance and angle tests, eq. 4 incremental model)
// on hand-built organised clouds whose regions can be counted by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/planes/plane_growing.h"
#include "core/planes/plane_model.h"
#include "core/planes/region_grower.h"
#include "tests/core/planes/hand_cloud.h"

namespace tunnelmap {
namespace {

using testing::hand_cloud;
using testing::tilted;

constexpr float kPitch = 0.01f;  // 10 mm between neighbouring points: well inside the 40 mm candidate distance
const Eigen::Vector3f kFacing(0, 0, -1);  // normal of the plane z = 1 m, facing the camera

struct Region {
  long points;
  Eigen::Vector3d mean_point, unit_normal;
  int u0, v0, u1, v1;
};

// Seeds and grows over every pixel in row order like the every-pixel path of extract_planes,
// keeping every region (no size limit); `labels` receives the label image.
std::vector<Region> grow_all(const OrganizedCloud& cloud, const GrowOptions& options,
                             std::vector<std::int32_t>& labels) {
  RegionGrower g;
  g.reset(cloud, options);
  std::vector<Region> out;
  for (int v = 0; v < cloud.height; ++v)
    for (int u = 0; u < cloud.width; ++u) {
      if (!g.seedable(u, v)) continue;
      PlaneModel m;
      if (!g.seed(u, v, m)) continue;
      g.grow(u, v, static_cast<std::int32_t>(out.size()) + 1, m);
      out.push_back({m.count(), m.mean_point(), m.mean_normal().normalized(), g.bbox_u0, g.bbox_v0,
                     g.bbox_u1, g.bbox_v1});
    }
  g.export_labels(labels);
  return out;
}

// The plane z = 1 m on a 10 mm grid, normals facing the camera; `odd` may change one pixel.
template <class Odd>
OrganizedCloud flat_plane(int w, int h, Odd odd) {
  return hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f);
    n = kFacing;
    odd(u, v, p, n);
  });
}

std::int32_t label_at(const std::vector<std::int32_t>& labels, int w, int u, int v) {
  return labels[static_cast<std::size_t>(v) * w + u];
}

TEST(RegionGrower, TwoPlanesMeetingAtARightAngleGiveTwoRegions) {
  // Columns 0..19: the plane z = 1 (normal -z); columns 20..39: the plane x = 0.2 (normal -x),
  // receding from the shared edge at x = 0.2, z = 1. 20 x 20 pixels each.
  const OrganizedCloud cloud = hand_cloud(40, 20, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    if (u < 20) {
      p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f), n = kFacing;
    } else {
      p = Eigen::Vector3f(0.2f, v * kPitch, 1.0f + (u - 20) * kPitch), n = Eigen::Vector3f(-1, 0, 0);
    }
  });
  std::vector<std::int32_t> labels;
  const std::vector<Region> regions = grow_all(cloud, GrowOptions{}, labels);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].points, 400);
  EXPECT_EQ(regions[1].points, 400);
  EXPECT_LT((regions[0].unit_normal - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  EXPECT_LT((regions[1].unit_normal - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-9);
  EXPECT_NEAR(regions[0].mean_point.x(), 0.095, 1e-6);  // mean of columns 0..19 at 10 mm
  EXPECT_NEAR(regions[1].mean_point.z(), 1.095, 1e-6);
  EXPECT_EQ(regions[1].u0, 20);
  EXPECT_EQ(regions[1].u1, 39);
  EXPECT_EQ(regions[1].v0, 0);
  EXPECT_EQ(regions[1].v1, 19);
  for (int v = 0; v < 20; ++v)
    for (int u = 0; u < 40; ++u) ASSERT_EQ(label_at(labels, 40, u, v), u < 20 ? 1 : 2) << u << "," << v;
}

TEST(RegionGrower, PointBeyondEpsilonIsNotJoined) {
  // One point 20 mm in front of the plane; epsilon 15 mm. Its normal agrees, so only the eq. 2
  // distance test can keep it out (it is 22 mm from its neighbours: a candidate).
  const OrganizedCloud cloud = flat_plane(20, 20, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    if (u == 10 && v == 10) p.z() -= 0.020f;
  });
  GrowOptions opt;
  opt.distance_m = 0.015;
  std::vector<std::int32_t> labels;
  const std::vector<Region> regions = grow_all(cloud, opt, labels);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].points, 399);
  EXPECT_EQ(label_at(labels, 20, 10, 10), 0);
  EXPECT_EQ(label_at(labels, 20, 11, 10), 1);
}

TEST(RegionGrower, PointWithinEpsilonIsJoined) {
  const OrganizedCloud cloud = flat_plane(20, 20, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    if (u == 10 && v == 10) p.z() -= 0.010f;  // 10 mm off, epsilon 15 mm
  });
  GrowOptions opt;
  opt.distance_m = 0.015;
  std::vector<std::int32_t> labels;
  const std::vector<Region> regions = grow_all(cloud, opt, labels);
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].points, 400);
  EXPECT_EQ(label_at(labels, 20, 10, 10), 1);
}

TEST(RegionGrower, NormalWithinLambdaJoinsAndBeyondLambdaDoesNot) {
  // lambda = 4 deg. A point on the plane whose normal is 3.5 deg off joins; 4.5 deg off does not
  // (the other 399 normals hold the mean normal within 0.01 deg of the plane's).
  for (const double off_deg : {3.5, 4.5}) {
    const OrganizedCloud cloud = flat_plane(20, 20, [&](int u, int v, Eigen::Vector3f&, Eigen::Vector3f& n) {
      if (u == 10 && v == 10) n = tilted(kFacing, off_deg);
    });
    GrowOptions opt;
    opt.angle_deg = 4.0;
    std::vector<std::int32_t> labels;
    const std::vector<Region> regions = grow_all(cloud, opt, labels);
    ASSERT_EQ(regions.size(), 1u) << off_deg;
    const bool joins = off_deg < 4.0;
    EXPECT_EQ(regions[0].points, joins ? 400 : 399) << off_deg;
    EXPECT_EQ(label_at(labels, 20, 10, 10), joins ? 1 : 0) << off_deg;
  }
}

TEST(RegionGrower, IncrementalModelEqualsBatchMeanOfMembers) {
  // A plane with a 2 mm ripple and normals wobbling by up to 1 deg: every pixel joins, and the
  // eq. 4 model refreshed join by join holds the same means as one pass over the members.
  const OrganizedCloud cloud = hand_cloud(30, 20, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f + 0.002f * std::sin(0.7f * u + 1.3f * v));
    n = tilted(kFacing, std::sin(1.1 * u + 0.3 * v));
  });
  RegionGrower g;
  g.reset(cloud, GrowOptions{});
  PlaneModel model;
  ASSERT_TRUE(g.seed(0, 0, model));
  g.grow(0, 0, 1, model);
  ASSERT_EQ(model.count(), 600);
  ASSERT_EQ(g.members().size(), 600u);
  Eigen::Vector3d sum_p = Eigen::Vector3d::Zero(), sum_n = Eigen::Vector3d::Zero();
  for (const RegionGrower::Member& m : g.members()) {
    sum_p += cloud.points[cloud.index(m.u, m.v)].cast<double>();
    sum_n += cloud.normals[cloud.index(m.u, m.v)].cast<double>();
  }
  EXPECT_LT((model.mean_point() - sum_p / 600.0).norm(), 1e-12);
  EXPECT_LT((model.mean_normal() - sum_n / 600.0).norm(), 1e-12);
  EXPECT_NEAR(model.mean_point().x(), 0.145, 1e-6);
}

TEST(RegionGrower, CoplanarPointsBeyondCandidateDistanceStartANewRegion) {
  // One plane, but columns 10.. sit 50 mm further right: the gap between columns 9 and 10 is
  // 60 mm, beyond the 40 mm candidate distance, so growth does not cross it.
  const OrganizedCloud cloud = hand_cloud(20, 10, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch + (u >= 10 ? 0.05f : 0.0f), v * kPitch, 1.0f);
    n = kFacing;
  });
  GrowOptions opt;
  opt.candidate_distance_m = 0.040;
  std::vector<std::int32_t> labels;
  const std::vector<Region> regions = grow_all(cloud, opt, labels);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].points, 100);
  EXPECT_EQ(regions[1].points, 100);
  EXPECT_EQ(regions[0].u1, 9);
  EXPECT_EQ(regions[1].u0, 10);
  // Gap of 30 mm instead: one region.
  const OrganizedCloud near = hand_cloud(20, 10, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch + (u >= 10 ? 0.02f : 0.0f), v * kPitch, 1.0f);
    n = kFacing;
  });
  EXPECT_EQ(grow_all(near, opt, labels).size(), 1u);
}

TEST(RegionGrower, ReleasedRegionLeavesNoLabelsAndNeverSeedsAgain) {
  const OrganizedCloud cloud = flat_plane(8, 6, [](int, int, Eigen::Vector3f&, Eigen::Vector3f&) {});
  RegionGrower g;
  g.reset(cloud, GrowOptions{});
  PlaneModel model;
  ASSERT_TRUE(g.seed(0, 0, model));
  g.grow(0, 0, 1, model);
  ASSERT_EQ(model.count(), 48);
  g.release();
  std::vector<std::int32_t> labels;
  g.export_labels(labels);
  ASSERT_EQ(labels.size(), 48u);
  for (std::int32_t l : labels) EXPECT_EQ(l, 0);
  for (int v = 0; v < 6; ++v)
    for (int u = 0; u < 8; ++u) EXPECT_FALSE(g.seedable(u, v)) << u << "," << v;
  PlaneModel again;
  EXPECT_FALSE(g.seed(2, 2, again));
}

TEST(RegionGrower, EveryPixelGrowingDropsRegionsBelowMinPoints) {
  // min_points is applied by the grower's caller: through extract_planes at grid step 1 (the
  // paper's every-pixel growing). Two patches split by pixels without a normal: 8 x 5 = 40
  // points and 13 x 3 = 39 points; min_points 40 keeps the first only.
  const OrganizedCloud cloud = hand_cloud(30, 12, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f& n) {
    p = Eigen::Vector3f(u * kPitch, v * kPitch, 1.0f);
    const bool a = u >= 1 && u < 9 && v >= 1 && v < 6;
    const bool b = u >= 12 && u < 25 && v >= 7 && v < 10;
    if (a || b) n = kFacing;
  });
  GrowOptions opt;
  opt.cell_px = 0;  // the pixel grid
  opt.grid_step = 1;
  opt.min_points = 40;
  opt.min_area_m2 = 0.0;
  opt.compute_contours = false;
  const PlaneSegments planes = extract_planes(cloud, opt);
  ASSERT_EQ(planes.planes.size(), 1u);
  EXPECT_EQ(planes.planes[0].points, 40);
  EXPECT_EQ(planes.planes[0].bbox_u0, 1);
  EXPECT_EQ(planes.planes[0].bbox_u1, 8);
  opt.min_points = 39;
  EXPECT_EQ(extract_planes(cloud, opt).planes.size(), 2u);
}

}  // namespace
}  // namespace tunnelmap
