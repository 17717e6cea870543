// The frame chosen to show a station: the one looking at it from nearest 1.5 m ahead, only
// frames that found the tunnel and look down it, and the station's distance ahead of it.
#include <gtest/gtest.h>

#include "core/mapping/station_frames.h"

namespace tunnelmap {
namespace {

// Camera at station `s` on the axis (world +x), looking along +x (or -x when `back`).
Eigen::Isometry3d camera_at(double s, bool back = false) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  // Camera z forward, y down, x right; world z up.
  Eigen::Matrix3d R;
  R.col(2) = Eigen::Vector3d(back ? -1 : 1, 0, 0);
  R.col(1) = Eigen::Vector3d(0, 0, -1);
  R.col(0) = R.col(1).cross(R.col(2));
  T.linear() = R;
  T.translation() = Eigen::Vector3d(s, 0, 0);
  return T;
}

StationMap map_along_x() {
  StationMap m;
  m.ok = true;
  m.origin = Eigen::Vector3d(-1.0, 0, 0);  // station 0 at world x = -1
  m.axis = Eigen::Vector3d::UnitX();
  return m;
}

TEST(StationFrames, TheCameraNearest1_5mBehindTheStationWins) {
  const StationMap m = map_along_x();
  const std::vector<Eigen::Isometry3d> poses = {camera_at(0.0), camera_at(1.0), camera_at(2.0)};
  // Station 3.5 is world x 2.5: 2.5, 1.5 and 0.5 m ahead of the three cameras.
  const auto v = frame_for_station(m, poses, {true, true, true}, 3.5);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->frame, 1);
  EXPECT_NEAR(v->ahead_m, 1.5, 1e-12);
}

TEST(StationFrames, FramesWithoutTheTunnelOrBehindTheStationAreNeverChosen) {
  const StationMap m = map_along_x();
  const std::vector<Eigen::Isometry3d> poses = {camera_at(0.0), camera_at(1.0), camera_at(4.0)};
  const auto v = frame_for_station(m, poses, {true, false, true}, 3.5);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->frame, 0);  // frame 1 lost the tunnel; frame 2 is past the station
  EXPECT_NEAR(v->ahead_m, 2.5, 1e-12);
  EXPECT_FALSE(frame_for_station(m, poses, {true, true, true}, 10.0).has_value());  // 5+ m ahead of all
}

TEST(StationFrames, ACameraLookingBackSeesStationsBehindIt) {
  const StationMap m = map_along_x();
  const std::vector<Eigen::Isometry3d> poses = {camera_at(4.0, true)};
  const auto v = frame_for_station(m, poses, {true}, 3.0);  // world x 2: 2 m in front of it
  ASSERT_TRUE(v.has_value());
  EXPECT_NEAR(v->ahead_m, 2.0, 1e-12);
  EXPECT_FALSE(frame_for_station(m, poses, {true}, 6.0).has_value());  // behind its back
}

TEST(StationFrames, TheMapRunsToItsSectionsEndsAndItsPlates) {
  StationMap m;
  for (int k = 0; k < 30; ++k) m.stations.push_back(Station{});
  for (int k = 0; k < 30; ++k) m.stations[k].station_m = 0.75 + 0.1 * k;  // 0.75 .. 3.65
  m.sections = {{0.7, 2.0, 0.9, 1.2}, {2.0, 3.7, 0.8, 1.1}};
  MapExtent e = map_extent(m);
  EXPECT_DOUBLE_EQ(e.from_m, 0.7);
  EXPECT_DOUBLE_EQ(e.to_m, 3.7);  // half a station past the last one
  EXPECT_TRUE(e.contains(3.69));
  EXPECT_FALSE(e.contains(3.71));
  Diaphragm end_wall;
  end_wall.station_m = 4.2;  // seen ahead, beyond the stations
  m.girder.diaphragms.push_back(end_wall);
  e = map_extent(m);
  EXPECT_DOUBLE_EQ(e.to_m, 4.2);
  EXPECT_TRUE(e.contains(4.0));
  EXPECT_FALSE(e.contains(0.6));
}

}  // namespace
}  // namespace tunnelmap
