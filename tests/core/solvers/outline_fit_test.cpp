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

}  // namespace
}  // namespace tunnelmap
