// The manhole outline fit on rims with known shape: the shape is told apart, the size and centre
// come out within a few millimetres of the truth under pixel-level noise and outliers, and a rim
// seen only in part is recognised as such.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/solvers/outline_fit.h"

namespace tunnelmap {
namespace {

// Points on an axis-aligned ellipse (centre c, semi-axes a, b), with Gaussian noise of `sigma`
// along the normal and a few far outliers, over the angles [from, to).
std::vector<Eigen::Vector2d> ellipse_rim(Eigen::Vector2d c, double a, double b, double sigma,
                                         double from, double to, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < 400; ++k) {
    const double t = from + (to - from) * k / 400.0;
    const Eigen::Vector2d p(a * std::cos(t), b * std::sin(t));
    const Eigen::Vector2d n = Eigen::Vector2d(p.x() / (a * a), p.y() / (b * b)).normalized();
    out.push_back(c + p + noise(rng) * n);
  }
  for (int k = 0; k < 8; ++k) out.push_back(c + Eigen::Vector2d(0.05 * k - 0.2, 0.6));  // clutter
  return out;
}

// Points on a rounded rectangle (half sizes A, B, corner radius r) with normal noise.
std::vector<Eigen::Vector2d> rounded_rectangle_rim(Eigen::Vector2d c, double A, double B, double r,
                                                   double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector2d> out;
  const double sx = A - r, sy = B - r;
  for (int k = 0; k < 100; ++k) {  // the four straight sides
    const double f = -1.0 + 2.0 * k / 100.0;
    out.push_back(c + Eigen::Vector2d(A + noise(rng), f * sy));
    out.push_back(c + Eigen::Vector2d(-A + noise(rng), f * sy));
    out.push_back(c + Eigen::Vector2d(f * sx, B + noise(rng)));
    out.push_back(c + Eigen::Vector2d(f * sx, -B + noise(rng)));
  }
  for (int q = 0; q < 4; ++q)  // the corner arcs
    for (int k = 0; k < 30; ++k) {
      const double t = (q + k / 30.0) * M_PI / 2;
      const Eigen::Vector2d corner((q == 0 || q == 3) ? sx : -sx, q < 2 ? sy : -sy);
      out.push_back(c + corner + (r + noise(rng)) * Eigen::Vector2d(std::cos(t), std::sin(t)));
    }
  return out;
}

TEST(OutlineFit, AnEllipseIsAnEllipseOfItsSize) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto rim = ellipse_rim({0.02, 0.55}, 0.225, 0.35, 0.003, 0, 2 * M_PI, seed);
    const auto f = fit_manhole_outline(rim);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->shape, "ellipse");
    EXPECT_NEAR(f->half_width_m, 0.225, 0.002);
    EXPECT_NEAR(f->half_height_m, 0.35, 0.002);
    EXPECT_NEAR(f->center.x(), 0.02, 0.002);
    EXPECT_NEAR(f->center.y(), 0.55, 0.002);
    EXPECT_LT(f->median_residual_m, 0.004);
    EXPECT_EQ(rim_directions(rim, f->center), 8);
  }
}

TEST(OutlineFit, ARoundedRectangleIsToldFromAnEllipse) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const auto rim = rounded_rectangle_rim({-0.01, 0.6}, 0.25, 0.4, 0.08, 0.003, seed);
    const auto f = fit_manhole_outline(rim);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->shape, "rounded_rectangle");
    EXPECT_NEAR(2 * f->half_width_m, 0.50, 0.004);
    EXPECT_NEAR(2 * f->half_height_m, 0.80, 0.004);
    EXPECT_NEAR(f->corner_radius_m, 0.08, 0.015);
    EXPECT_LT(f->rectangle_residual_m, 0.7 * f->ellipse_residual_m);
  }
}

TEST(OutlineFit, ARimSeenOnlyInPartCoversFewDirections) {
  const auto rim = ellipse_rim({0.0, 0.5}, 0.225, 0.35, 0.003, 0, M_PI, 3);  // upper half only
  const auto f = fit_manhole_outline(rim);
  ASSERT_TRUE(f);
  EXPECT_LE(rim_directions(rim, f->center), 5);
  EXPECT_FALSE(fit_manhole_outline(std::vector<Eigen::Vector2d>(5, Eigen::Vector2d::Zero())));
}


// Views of one rounded rectangle, each moved by its own pose error (two saw only the top of
// the rim); a view of four stray points rides along. Fitted view by view the outline is the
// opening's, each view's shift undoes its move against the largest view's, and the stray view
// stays where it is.
TEST(OutlineFit, ViewsMovedByTheirPosesAgreeOnTheOpening) {
  const Eigen::Vector2d c(0.01, 0.6);
  constexpr int kViews = 5;
  const Eigen::Vector2d moves[kViews] = {{0.0, 0.0}, {0.006, -0.008}, {-0.004, 0.005}, {0.0, 0.022}, {0.003, 0.026}};
  std::vector<std::vector<Eigen::Vector2d>> views;
  for (int v = 0; v < kViews; ++v) {
    std::vector<Eigen::Vector2d> rim;
    for (const Eigen::Vector2d& p : rounded_rectangle_rim(c, 0.25, 0.31, 0.09, 0.002, 10 + v))
      if (v < 3 || p.y() > c.y() + 0.1) rim.push_back(p + moves[v]);  // views 3 and 4: the top
    views.push_back(rim);
  }
  views.push_back(std::vector<Eigen::Vector2d>(4, c + Eigen::Vector2d(0.3, 0.4)));
  const auto joint = fit_manhole_outline(views, 0.02);
  ASSERT_TRUE(joint);
  EXPECT_EQ(joint->shape, "rounded_rectangle");
  EXPECT_NEAR(2 * joint->half_width_m, 0.50, 0.002);
  EXPECT_NEAR(2 * joint->half_height_m, 0.62, 0.002);
  ASSERT_EQ(joint->view_shifts.size(), kViews + 1u);
  Eigen::Vector2d mean_move = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& m : moves) mean_move += m / kViews;
  std::size_t largest = 0;
  for (std::size_t v = 1; v < kViews; ++v)
    if (views[v].size() > views[largest].size()) largest = v;
  for (int v = 0; v < kViews; ++v)
    EXPECT_LT((joint->view_shifts[v] + moves[v] - moves[largest]).norm(), 0.003) << v;
  EXPECT_EQ(joint->view_shifts[kViews], Eigen::Vector2d::Zero());
  EXPECT_LT((joint->center - (c + mean_move)).norm(), 0.003);

  // Pooled as they are, the top views lift the outline's top.
  const auto pooled = fit_manhole_outline(views, 0.0);
  ASSERT_TRUE(pooled);
  EXPECT_GT(2 * pooled->half_height_m, 0.62 + 0.004);
}

}  // namespace
}  // namespace tunnelmap
