// The cell order's pixel labels (cell_pixel_labels.h): which cells keep all their pixels and
// which are assigned pixel by pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/planes/cell_pixel_labels.h"
#include "core/planes/plane_growing.h"
#include "tests/core/planes/hand_cloud.h"

using namespace tunnelmap;
using tunnelmap::testing::hand_cloud;

TEST(CellPixelLabels, TwoPlanesThatCoincideAtTheirBorderMeetAlongTheCellBorder) {
  // A wall 2 m away folded by 7.5 degrees along the cell border u = 80, with 0.5 mm of depth
  // noise: two planes (the fold exceeds the angle test), nearly coincident next to the fold.
  // Pixels there lie within epsilon of both; the cells on each side keep theirs, so the border
  // is the cell border and not a line of noise-picked pixels.
  const int w = 160, h = 120;
  const double f = 570.0, t = 7.5 * M_PI / 180.0, x0 = (80 - w / 2.0) / f * 2.0;
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.0005);
  OrganizedCloud c = hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const double a = (u - w / 2.0) / f, b = (v - h / 2.0) / f;
    const double z = (u < 80 ? 2.0 : (2.0 - x0 * std::tan(t)) / (1.0 - a * std::tan(t))) + noise(rng);
    p = Eigen::Vector3f(static_cast<float>(a * z), static_cast<float>(b * z), static_cast<float>(z));
  });
  c.intrinsics.fx = c.intrinsics.fy = f;
  c.intrinsics.cx = w / 2.0, c.intrinsics.cy = h / 2.0;
  GrowOptions o;
  o.cell_px = 8;
  const PlaneSegments planes = extract_planes(c, o);
  ASSERT_EQ(planes.planes.size(), 2u);
  const int left_id = planes.labels[c.index(0, 0)];
  int crossed = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int id = planes.labels[c.index(u, v)];
      ASSERT_GT(id, 0) << u << "," << v;
      crossed += (id == left_id) != (u < 80);
    }
  EXPECT_EQ(crossed, 0);
  const double cos_fold = std::abs(planes.planes[0].normal.dot(planes.planes[1].normal));
  EXPECT_NEAR(std::acos(std::min(1.0, cos_fold)) * 180.0 / M_PI, 7.5, 0.3);
}

TEST(CellPixelLabels, ALabelledCellKeepsItsPixelsFromAPlaneAtItsCornerAndAFreeCellSharesThem) {
  // A flat wall at z = 2 m, 3 x 3 cells of 8 pixels. Plane 1 (the centre cell's) lies 10 mm in
  // front of the wall; plane 2 (the top-left cell's) is tilted by 45 degrees about the vertical
  // line u = 8, so the wall pixels near that line are nearer to it than to plane 1.
  const int w = 24, h = 24;
  const double f = 570.0;
  OrganizedCloud c = hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    p = Eigen::Vector3f(static_cast<float>((u - w / 2.0) / f * 2.0), static_cast<float>((v - h / 2.0) / f * 2.0),
                        2.0f);
  });
  CellGrid grid;
  compute_cell_fits(c, 8, 32, 0.0075, grid);
  ASSERT_EQ(grid.cols, 3);
  const float x8 = c.points[c.index(8, 0)].x(), s = static_cast<float>(std::sqrt(0.5));
  const std::vector<Eigen::Vector4f> planes = {{0.0f, 0.0f, -1.0f, 2.010f}, {s, 0.0f, -s, -(s * x8 - s * 2.0f)}};
  std::vector<std::int32_t> cell_labels(9, 0);
  cell_labels[grid.index(1, 1)] = 1;
  cell_labels[grid.index(0, 0)] = 2;
  std::vector<PixelTally> tallies(2);
  PlaneSegments out;
  out.width = w, out.height = h;
  assign_cell_pixels(c, grid, 0.015, cell_labels, planes, tallies, out);
  // The centre cell: plane 2 only touches its corner, so all 64 pixels stay plane 1's, though
  // columns 8-12 lie nearer to plane 2 (0-9.9 mm against 10 mm).
  for (int v = 8; v < 16; ++v)
    for (int u = 8; u < 16; ++u) EXPECT_EQ(out.labels[c.index(u, v)], 1) << u << "," << v;
  // The free cell below the top-left one: each pixel to the nearer plane within epsilon.
  int to1 = 0, to2 = 0;
  for (int v = 8; v < 16; ++v)
    for (int u = 0; u < 8; ++u) {
      const float d2 = std::abs(planes[1].head<3>().dot(c.points[c.index(u, v)]) + planes[1].w());
      EXPECT_EQ(out.labels[c.index(u, v)], d2 < 0.010f ? 2 : 1) << u << "," << v;
      (d2 < 0.010f ? to2 : to1)++;
    }
  EXPECT_GT(to1, 0);
  EXPECT_GT(to2, 0);
  long labelled = 0;
  for (const std::int32_t l : out.labels) labelled += l > 0;
  EXPECT_EQ(tallies[0].count + tallies[1].count, labelled);
}
