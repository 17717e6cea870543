// Stations past a girder's end wall are its corner's samples, not girder: they go.
#include "core/mapping/end_wall_trim.h"

#include <gtest/gtest.h>

namespace tunnelmap {
namespace {

// Stations every 0.1 m from 0.05 to 7.95 m; a 0.90 m wide section to 6 m, then 0.80 m.
StationMap eight_metres() {
  StationMap m;
  m.ok = true;
  for (int k = 0; k < 80; ++k) {
    Station st;
    st.station_m = 0.05 + 0.1 * k;
    st.width_m = st.station_m < 6.0 ? 0.90 : 0.80, st.height_m = 1.20;
    st.width_source = st.height_source = DimensionSource::Measured;
    m.stations.push_back(st);
  }
  m.sections = {{0.0, 6.0, 0.90, 1.20}, {6.0, 8.0, 0.80, 1.20}};
  return m;
}

Diaphragm plate(double station_m, const char* kind) {
  Diaphragm d;
  d.station_m = station_m;
  d.kind = kind;
  d.closed = std::string(kind) == "end_wall";
  return d;
}

const std::vector<std::array<double, 4>> kTwoSectionsWalls = {{0.45, 0.45, 0.6, 0.6}, {0.40, 0.40, 0.6, 0.6}};

TEST(EndWallTrim, TheStationPastTheLastEndWallGoesAndItsSectionEndsBeforeIt) {
  // The end wall at 7.88 m: the station 7.9-8.0 lies wholly beyond it; 7.8-7.9 holds 8 cm of girder.
  StationMap m = eight_metres();
  m.girder.diaphragms = {plate(3.0, "diaphragm"), plate(7.88, "end_wall")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  ASSERT_EQ(m.stations.size(), 79u);
  EXPECT_NEAR(m.stations.back().station_m, 7.85, 1e-9);
  ASSERT_EQ(m.sections.size(), 2u);
  EXPECT_NEAR(m.sections[1].to_m, 7.9, 1e-9);
  EXPECT_NEAR(m.sections[0].from_m, 0.0, 1e-9);
  EXPECT_EQ(walls.size(), 2u);
}

TEST(EndWallTrim, AnEndWallAtTheStartDropsTheStationsBeforeIt) {
  StationMap m = eight_metres();
  m.girder.diaphragms = {plate(0.21, "end_wall"), plate(3.0, "diaphragm")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  EXPECT_NEAR(m.stations.front().station_m, 0.25, 1e-9);  // 0.2-0.3 holds 9 cm of girder
  EXPECT_NEAR(m.sections.front().from_m, 0.2, 1e-9);
  EXPECT_NEAR(m.stations.back().station_m, 7.95, 1e-9);
}

TEST(EndWallTrim, EndWallsAtBothEndsKeepTheGirderBetweenThem) {
  // A short girder: 0.21 to 2.38 m between its end walls, walked over 8 m of stations (the
  // corner samples of a distant wall would never make so many; the rule must not care).
  StationMap m = eight_metres();
  m.girder.diaphragms = {plate(0.21, "end_wall"), plate(1.0, "diaphragm"), plate(2.38, "end_wall")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  EXPECT_NEAR(m.stations.front().station_m, 0.25, 1e-9);
  EXPECT_NEAR(m.stations.back().station_m, 2.35, 1e-9);
  ASSERT_EQ(m.sections.size(), 1u);  // the second section (6-8 m) lay wholly beyond
  EXPECT_NEAR(m.sections[0].from_m, 0.2, 1e-9);
  EXPECT_NEAR(m.sections[0].to_m, 2.4, 1e-9);
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_DOUBLE_EQ(walls[0][0], 0.45);
}

TEST(EndWallTrim, AFirstSectionWhollyBeforeTheEndWallGoesAndTheNextKeepsItsWalls) {
  StationMap m = eight_metres();
  m.sections = {{0.0, 0.2, 0.90, 1.20}, {0.2, 8.0, 0.80, 1.20}};
  m.sections[1].joint_seen = false, m.sections[1].joint_uncertainty_m = 0.15;
  m.girder.diaphragms = {plate(0.21, "end_wall"), plate(4.0, "diaphragm")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_NEAR(m.sections[0].from_m, 0.2, 1e-9);
  EXPECT_TRUE(m.sections[0].joint_seen);  // the first section has no joint before it
  EXPECT_DOUBLE_EQ(m.sections[0].joint_uncertainty_m, 0.0);
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_DOUBLE_EQ(walls[0][0], 0.40);  // the second section's walls
}

TEST(EndWallTrim, ALoneEndWallBoundsTheSideFewerMeasuredStationsLieOn) {
  // Stations past 7.88 m are many but unmeasured (context values); the measured girder lies
  // before the wall.
  StationMap m = eight_metres();
  for (int k = 0; k < 20; ++k) {
    Station st;
    st.station_m = 7.95 + 0.1 * (k + 1);
    st.width_source = st.height_source = DimensionSource::Context;
    m.stations.push_back(st);
  }
  m.sections.back().to_m = 10.0;
  m.girder.diaphragms = {plate(7.88, "end_wall")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  EXPECT_NEAR(m.stations.back().station_m, 7.85, 1e-9);
  EXPECT_NEAR(m.stations.front().station_m, 0.05, 1e-9);
}

TEST(EndWallTrim, ADiaphragmAtTheEndTrimsNothing) {
  // A plate with the girder beyond it, only not seen: the stations past it stay.
  StationMap m = eight_metres();
  m.girder.diaphragms = {plate(7.88, "diaphragm")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  EXPECT_FALSE(trim_beyond_end_walls(m, walls));
  EXPECT_EQ(m.stations.size(), 80u);
  EXPECT_NEAR(m.sections[1].to_m, 8.0, 1e-9);
}

TEST(EndWallTrim, ASectionWhollyBeyondTheEndWallGoesWithItsWalls) {
  StationMap m = eight_metres();
  m.sections = {{0.0, 7.9, 0.90, 1.20}, {7.9, 8.0, 0.80, 1.20}};
  m.girder.diaphragms = {plate(7.88, "end_wall")};
  std::vector<std::array<double, 4>> walls = kTwoSectionsWalls;
  ASSERT_TRUE(trim_beyond_end_walls(m, walls));
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_NEAR(m.sections[0].to_m, 7.9, 1e-9);
  ASSERT_EQ(walls.size(), 1u);
  EXPECT_DOUBLE_EQ(walls[0][0], 0.45);
}

}  // namespace
}  // namespace tunnelmap
