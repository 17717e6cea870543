// The truth centre line: stations of world points on a curve, found over the whole line or near
// a known point, agree.
#include <gtest/gtest.h>

#include <cmath>

#include "core/evaluation/truth_line.h"

namespace tunnelmap {
namespace {

// A 150 m radius arc, a point every 0.1 m over 30 m.
nlohmann::json arc() {
  nlohmann::json line = nlohmann::json::array();
  for (int k = 0; k <= 300; ++k) {
    const double s = 0.1 * k, a = s / 150.0;
    line.push_back({{"station_m", s}, {"point", {150.0 * std::sin(a), 150.0 * (1 - std::cos(a)), 0.5}}});
  }
  return line;
}

TEST(TruthLine, StationsOfPointsBesideACurveAgreeWhetherSearchedWhollyOrNearAKnownPoint) {
  const TruthLine line(arc());
  for (const double s : {3.0, 12.34, 27.91}) {
    const double a = s / 150.0;
    // 0.4 m to the side of the line and 0.3 m above it: the station is the line's own.
    const Eigen::Vector3d p(149.6 * std::sin(a), 150.0 - 149.6 * std::cos(a), 0.8);
    EXPECT_NEAR(line.station_of(p), s, 0.002) << s;
    const std::size_t near = line.nearest(Eigen::Vector3d(150.0 * std::sin(a - 0.02), 0.0, 0.5));
    EXPECT_NEAR(line.station_near(p, near, 70), s, 0.002) << s;
    const Eigen::Vector3d d = line.direction_at(p);
    EXPECT_NEAR(d.x(), std::cos(a), 1e-3);
    EXPECT_NEAR(d.y(), std::sin(a), 1e-3);
  }
}

}  // namespace
}  // namespace tunnelmap
