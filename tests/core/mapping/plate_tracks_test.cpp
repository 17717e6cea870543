#include "core/mapping/plate_tracks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace tunnelmap {
namespace {

// Counts the landmarks the tracks ask for.
struct Planes {
  int made = 0;
  int operator()() { return made++; }
};

TEST(PlateTracks, APlateFirstSeenFarAwayIsStillThatPlateWhenSeenNear) {
  // Seen through a manhole from 5.6 m: 9.5 mm of noise and 5 cm off. Walking up to it, the near
  // views (1.8 mm) agree with each other and differ from the first by 5 cm.
  PlateTracks tracks;
  Planes planes;
  const int far = tracks.view(8.712, 0.0095, 3.12, std::ref(planes));
  for (double camera : {3.88, 4.64, 5.44}) EXPECT_EQ(tracks.view(8.68, 0.007, camera, std::ref(planes)), far);
  EXPECT_EQ(tracks.view(8.661, 0.0018, 6.20, std::ref(planes)), far);
  EXPECT_EQ(tracks.view(8.663, 0.0018, 6.98, std::ref(planes)), far);
  EXPECT_EQ(planes.made, 1);
  // The near views decide where it is.
  EXPECT_NEAR(tracks.station_m(0), 8.662, 0.004);
}

TEST(PlateTracks, TwoPlatesAFewDecimetresApartStayTwo) {
  PlateTracks tracks;
  Planes planes;
  const int first = tracks.view(4.0, 0.002, 2.0, std::ref(planes));
  const int second = tracks.view(4.25, 0.002, 2.0, std::ref(planes));
  EXPECT_NE(first, second);
  EXPECT_EQ(tracks.view(4.01, 0.002, 2.5, std::ref(planes)), first);
  EXPECT_EQ(tracks.view(4.24, 0.002, 2.5, std::ref(planes)), second);
  EXPECT_EQ(planes.made, 2);
}

TEST(PlateTracks, ThePlateBehindIsRecognisedAfterTheOdometryDriftedAlongTheWalk) {
  // Seen last 16 m back, the odometry may have drifted 4 cm (1 cm per root metre): a view 12 cm
  // off is still within four standard deviations; one 25 cm off is not, nor beyond the gate.
  PlateTrackOptions options;
  options.drift_m_per_sqrt_m = 0.01;
  PlateTracks tracks(options);
  Planes planes;
  const int plate = tracks.view(10.0, 0.002, 8.0, std::ref(planes));
  EXPECT_EQ(tracks.view(10.12, 0.002, 24.0, std::ref(planes)), plate);
  PlateTracks fresh(options);
  fresh.view(10.0, 0.002, 8.0, std::ref(planes));
  EXPECT_NE(fresh.view(10.25, 0.002, 24.0, std::ref(planes)), plate);
  EXPECT_EQ(fresh.size(), 2);
}

TEST(PlateTracks, NearViewsOfOnePlaceNeedAtLeastTheSmallestReach) {
  // Exact views leave no noise, yet a plate 3 cm from a known one is the same plate.
  PlateTracks tracks;
  Planes planes;
  const int plate = tracks.view(6.0, 0.0, 4.0, std::ref(planes));
  EXPECT_EQ(tracks.view(6.03, 0.0, 4.0, std::ref(planes)), plate);
  EXPECT_NE(tracks.view(6.2, 0.0, 4.0, std::ref(planes)), plate);
}

TEST(PlateTracks, TellsWhetherAPlateLiesWithinAStretch) {
  PlateTracks tracks;
  Planes planes;
  tracks.view(4.5, 0.002, 1.0, std::ref(planes));
  EXPECT_TRUE(tracks.any_within(4.0, 5.0));
  EXPECT_FALSE(tracks.any_within(4.6, 8.0));
}

TEST(PlateTracks, FindsThePlateOfAStretchNearestAStation) {
  PlateTracks tracks;
  Planes planes;
  tracks.view(4.5, 0.002, 1.0, std::ref(planes));
  tracks.view(8.5, 0.002, 5.0, std::ref(planes));
  EXPECT_DOUBLE_EQ(tracks.nearest_within(4.0, 9.0, 7.0), 8.5);
  EXPECT_DOUBLE_EQ(tracks.nearest_within(4.0, 9.0, 6.0), 4.5);
  EXPECT_DOUBLE_EQ(tracks.nearest_within(4.0, 8.0, 7.0), 4.5);  // 8.5 lies outside
  EXPECT_TRUE(std::isnan(tracks.nearest_within(5.0, 8.0, 6.0)));
}

}  // namespace
}  // namespace tunnelmap
