// The station map's reference line: a straight line measures stations as a projection, and the
// line fitted to frame centres on a 150 m radius curve rising at 4 % and rolled by 3 degrees
// gives stations equal to the arc length and cuts cross-sections perpendicular to the curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/mapping/centreline_fit.h"

namespace tunnelmap {
namespace {

constexpr double kRadius = 150.0, kGradient = 0.04, kRollDeg = 3.0;

// The true centre line: a helix on the curve, `s` its arc length from the start.
struct Helix {
  double slope_factor = std::sqrt(1.0 + kGradient * kGradient);  // arc length per horizontal metre
  Eigen::Vector3d point(double s) const {
    const double h = s / slope_factor, a = h / kRadius;
    return {kRadius * std::sin(a), kRadius * (1.0 - std::cos(a)), kGradient * h};
  }
  Eigen::Vector3d axis(double s) const {
    const double a = s / slope_factor / kRadius;
    return Eigen::Vector3d(std::cos(a), std::sin(a), kGradient).normalized();
  }
  Eigen::Vector3d up(double s) const {  // vertical made perpendicular, then rolled about the axis
    const Eigen::Vector3d t = axis(s), z = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d u = (z - t * t.dot(z)).normalized();
    return Eigen::AngleAxisd(-kRollDeg * M_PI / 180.0, t) * u;
  }
};

TEST(Centreline, AStraightLineMeasuresStationsAsAProjection) {
  const Centreline line = Centreline::straight({1, 2, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ());
  const LinePosition p = line.locate({4.5, 2.3, -0.2});
  EXPECT_NEAR(p.station_m, 3.5, 1e-12);
  EXPECT_NEAR(p.lateral_m, 0.3, 1e-12);
  EXPECT_NEAR(p.vertical_m, -0.2, 1e-12);
  EXPECT_LT((line.to_world(3.5, 0.3, -0.2) - Eigen::Vector3d(4.5, 2.3, -0.2)).norm(), 1e-12);
}

TEST(CentrelineFit, StationsAreArcLengthAlongACurveThatRisesAndRolls) {
  // Frames every 0.3 m over 20 m, their centres scattered by 1 mm (as walls measure them).
  const Helix truth;
  std::vector<CentreSample> samples;
  for (int i = 0; i <= 66; ++i) {
    const double s = 0.3 * i, wobble = 0.001 * std::sin(7.3 * i);
    samples.push_back({truth.point(s) + wobble * truth.up(s), truth.axis(s), truth.up(s)});
  }
  const std::optional<Centreline> line =
      fit_centreline(samples, truth.point(0.0), Eigen::Vector3d::UnitX(), StationMapOptions());
  ASSERT_TRUE(line);
  EXPECT_FALSE(line->is_straight());
  for (double s = 0.5; s < 19.5; s += 0.5) {
    // A wall point 0.4 m left and 0.6 m above the centre, in the girder's rolled frame.
    const Eigen::Vector3d left = truth.up(s).cross(truth.axis(s));
    const LinePosition p = line->locate(truth.point(s) + 0.4 * left + 0.6 * truth.up(s));
    EXPECT_NEAR(p.station_m, s, 1e-3) << s;
    EXPECT_NEAR(p.lateral_m, 0.4, 1e-3) << s;
    EXPECT_NEAR(p.vertical_m, 0.6, 1e-3) << s;
    const CentrelineFrame f = line->frame_at(s);
    EXPECT_LT((f.point - truth.point(s)).norm(), 1e-3) << s;
    EXPECT_GT(f.axis.dot(truth.axis(s)), std::cos(0.05 * M_PI / 180.0)) << s;
  }
}

TEST(CentrelineFit, StretchesNoFrameMeasuredAreBridgedNotGuessedFromOneStop) {
  // A robot's walk: stops 0.74 m apart, two frames at each a few millimetres apart, and no
  // centre where the frames near a plate lose a wall: 3.7 m after the first two stops, then
  // 2.2 m of every 3.7 m compartment. A slope fitted across one stop's two frames is their
  // noise over millimetres; such nodes stood up to a metre off the girder.
  const Helix truth;
  std::vector<CentreSample> samples;
  std::vector<double> stops{0.0, 0.74};
  for (double s = 4.45; s < 30.0; s += 0.74)
    if (std::fmod(s - 4.45, 3.7) < 1.5) stops.push_back(s);
  int k = 0;
  for (const double stop : stops)
    for (const double nudge : {0.0, 0.004}) {
      const double s = stop + nudge, wobble = 0.001 * std::sin(7.3 * ++k);
      samples.push_back({truth.point(s) + wobble * truth.up(s), truth.axis(s), truth.up(s)});
    }
  const std::optional<Centreline> line =
      fit_centreline(samples, truth.point(0.0), Eigen::Vector3d::UnitX(), StationMapOptions());
  ASSERT_TRUE(line);
  // Where frames measured, the line is as good as their centres; across the stretches none
  // measured, a smooth bridge from both sides (the curve's own sagitta over 3.7 m is 11 mm).
  for (double s = 0.25; s < stops.back(); s += 0.25) {
    const bool measured = std::any_of(stops.begin(), stops.end(), [&](double stop) { return std::abs(s - stop) <= 0.4; });
    const double mm = measured ? 2e-3 : 6e-3, deg = measured ? 0.4 : 0.6;
    const LinePosition p = line->locate(truth.point(s) + 0.3 * truth.up(s));
    EXPECT_NEAR(p.station_m, s, mm) << s;
    EXPECT_NEAR(p.lateral_m, 0.0, mm) << s;
    EXPECT_NEAR(p.vertical_m, 0.3, mm) << s;
    EXPECT_GT(line->frame_at(s).axis.dot(truth.axis(s)), std::cos(deg * M_PI / 180.0)) << s;
  }
}

TEST(CentrelineFit, AWalkShorterThanTwoWindowsKeepsTheStraightAxis) {
  const Helix truth;
  std::vector<CentreSample> samples;
  for (int i = 0; i <= 10; ++i) samples.push_back({truth.point(0.5 * i), truth.axis(0.5 * i), truth.up(0.5 * i)});
  EXPECT_FALSE(fit_centreline(samples, truth.point(0.0), Eigen::Vector3d::UnitX(), StationMapOptions()));
}

}  // namespace
}  // namespace tunnelmap
