// The cell order's pass over the pixels no cell plane took (residual_growth.h): a band seen
// nearly edge-on, narrower than a cell, between two walls facing the camera.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "core/params/parameters.h"
#include "core/planes/grow_options.h"
#include "core/planes/plane_growing.h"
#include "tests/core/planes/hand_cloud.h"

using namespace tunnelmap;
using tunnelmap::testing::hand_cloud;

namespace {

constexpr int kW = 200, kH = 120, kBand0 = 100, kBand1 = 106;  // band columns [kBand0, kBand1)
constexpr double kF = 570.0;

// Wall A (z = 2.3 m) left of the band, wall B (z = 2.6 m) right of it; in the band the depth
// grows by 3 cm per column, so the band's plane is seen at about 83 degrees of incidence. Half
// a millimetre of deterministic noise everywhere.
OrganizedCloud band_scene() {
  OrganizedCloud c = hand_cloud(kW, kH, [](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const double z0 = u < kBand0 ? 2.3 : u < kBand1 ? 2.05 + 0.03 * (u - kBand0) : 2.6;
    const double z = z0 + 0.0005 * (((u * 7 + v * 13) % 5) - 2) / 2.0;
    p = Eigen::Vector3f(static_cast<float>((u - kW / 2.0) / kF * z), static_cast<float>((v - kH / 2.0) / kF * z),
                        static_cast<float>(z));
  });
  c.intrinsics.fx = c.intrinsics.fy = kF;
  c.intrinsics.cx = kW / 2.0, c.intrinsics.cy = kH / 2.0;
  c.normals.clear();  // the cell order reads none
  return c;
}

// The band's plane: through its columns' points, spanned by the image's y direction.
Eigen::Vector3d band_normal(const OrganizedCloud& c) {
  const Eigen::Vector3d a = c.points[c.index(kBand0 + 1, kH / 2)].cast<double>();
  const Eigen::Vector3d b = c.points[c.index(kBand1 - 1, kH / 2)].cast<double>();
  const Eigen::Vector3d up = c.points[c.index(kBand0 + 1, 0)].cast<double>() - a;
  return (b - a).cross(up).normalized();
}

const PlaneSegment* band_plane(const PlaneSegments& planes, const Eigen::Vector3d& normal) {
  for (const PlaneSegment& p : planes.planes)
    if (std::abs(p.normal.dot(normal)) > std::cos(3.0 * M_PI / 180.0)) return &p;
  return nullptr;
}

}  // namespace

TEST(ResidualGrowth, ABandNarrowerThanACellSeenEdgeOnIsFound) {
  const OrganizedCloud cloud = band_scene();
  const Eigen::Vector3d n = band_normal(cloud);
  const Eigen::Vector3d centre = cloud.points[cloud.index(kBand0 + 3, kH / 2)].cast<double>();
  ASSERT_GT(std::acos(std::abs(n.dot(centre.normalized()))) * 180.0 / M_PI, 80.0);  // seen edge-on

  GrowOptions options = grow_options(Parameters());
  options.cell_px = 8;
  // The lab preset's epsilon: a cell half on a wall and half on the band is a stepped surface
  // 1-2 cm across, far from one plane at 4 mm RMS.
  options.distance_m = 0.008;
  options.edge_on_pass = false;
  const PlaneSegments cells_only = extract_planes(cloud, options);
  EXPECT_EQ(band_plane(cells_only, n), nullptr);  // every cell it crosses also holds a wall
  EXPECT_EQ(cells_only.planes.size(), 2u);

  options.edge_on_pass = true;
  const PlaneSegments with_pass = extract_planes(cloud, options);
  ASSERT_EQ(with_pass.planes.size(), 3u);
  const PlaneSegment* band = band_plane(with_pass, n);
  ASSERT_NE(band, nullptr);
  EXPECT_TRUE(band->edge_on);
  // At least four of its six columns over the full height; none of the walls' pixels.
  EXPECT_GE(band->points, 4 * kH);
  EXPECT_LE(band->points, (kBand1 - kBand0) * kH);
  int outside = 0;
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u)
      if (with_pass.labels[cloud.index(u, v)] == band->id && (u < kBand0 || u >= kBand1)) ++outside;
  EXPECT_EQ(outside, 0);
  EXPECT_NEAR(band->rms_m, 0.0, 0.001);
  // The walls keep what they had.
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(with_pass.planes[i].points, cells_only.planes[i].points);
}
