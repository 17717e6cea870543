// Where between two sections their joint may lie, from the stations' sizes and the walls.
#include "core/mapping/joint_stretch.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tunnelmap {
namespace {

const double kNaN = std::nan("");

// 1.20 m high before, 1.23 m after; `lead` stations, then stations 0-4 and 13-19 (counted
// from the lead) measured the height whole.
struct Heights {
  int lead;
  std::vector<double> w, h;
  SectionRun a, b;
  explicit Heights(int lead_stations = 0)
      : lead(lead_stations), a{0, lead + 11, 0.80, 1.20}, b{lead + 12, lead + 19, 0.80, 1.23} {
    for (int k = 0; k < lead + 20; ++k) {
      const int i = k - lead;
      w.push_back(0.80);
      h.push_back(i <= 4 ? 1.20 : i >= 13 ? 1.23 : kNaN);
    }
  }
  // Walls per station: sides at 0.40, floor at 0.60 (unseen 5-12), the roof at `roof(i)`.
  template <typename Roof>
  std::vector<std::array<double, 4>> walls(Roof roof) const {
    std::vector<std::array<double, 4>> out;
    for (int k = 0; k < lead + 20; ++k) {
      const int i = k - lead;
      out.push_back({0.40, 0.40, i >= 5 && i <= 12 ? kNaN : 0.60, roof(i)});
    }
    return out;
  }
  JointStretch narrowed(const std::vector<std::array<double, 4>>& wall_m) const {
    return narrowed_by_walls(a, b, stretch_between(a, b, w, h), wall_m);
  }
};

TEST(JointStretch, TheSizesBoundTheStretchAndItsMiddleHalvesIt) {
  const Heights t;
  const JointStretch s = stretch_between(t.a, t.b, t.w, t.h);
  EXPECT_EQ(stepping_dimension(t.a, t.b), 1);
  EXPECT_EQ(s.last_a, 4);
  EXPECT_EQ(s.first_b, 13);
  EXPECT_EQ(s.unmeasured(), 8);
  EXPECT_EQ(s.middle(), 9);
}

TEST(JointStretch, ARoofThatRisesAloneNarrowsTheStretchToWhereItStepped) {
  const Heights t;
  // The roof seen at 9-12: 0.60 up to 10, 0.63 from 11.
  const auto roof = [](int i) { return i >= 5 && i <= 8 ? kNaN : i <= 10 ? 0.60 : 0.63; };
  const JointStretch s = t.narrowed(t.walls(roof));
  EXPECT_EQ(s.last_a, 10);
  EXPECT_EQ(s.first_b, 11);
  EXPECT_EQ(s.unmeasured(), 0);
}

TEST(JointStretch, OnlyTheStationsNextToTheStretchGiveTheWallsPositions) {
  // Twenty stations before, the roof lay 20 mm higher (the centre line wanders over a
  // section's length): the section's median roof is that one, the step next to the stretch
  // is still 30 mm.
  const Heights t(20);
  const auto roof = [](int i) { return i >= 5 && i <= 8 ? kNaN : i < 0 ? 0.62 : i <= 10 ? 0.60 : 0.63; };
  const JointStretch s = t.narrowed(t.walls(roof));
  EXPECT_EQ(s.last_a, t.lead + 10);
  EXPECT_EQ(s.first_b, t.lead + 11);
}

TEST(JointStretch, AWallThatStaysOrCarriesHalfTheStepTellsNothing) {
  const Heights t;
  const auto stays = [](int i) { return i >= 5 && i <= 8 ? kNaN : 0.60; };
  EXPECT_EQ(t.narrowed(t.walls(stays)).unmeasured(), 8);
  // 15 mm of the 30 mm step: the roof's own share is no more than the centre line's error.
  const auto half = [](int i) { return i >= 5 && i <= 8 ? kNaN : i <= 10 ? 0.60 : 0.615; };
  EXPECT_EQ(t.narrowed(t.walls(half)).unmeasured(), 8);
}

}  // namespace
}  // namespace tunnelmap
