#include "core/mapping/wall_band_grid.h"

#include <gtest/gtest.h>

namespace tunnelmap {
namespace {

TEST(WallBandGrid, CutsTheBandThatHoldsAPlateAtThePlate) {
  const WallBandGrid grid(1.0, {5.5, 2.0});
  // Cell 5 holds the plate at 5.5: the wall before it and the wall past it are two bands, each
  // half a band long.
  const long before = grid.band(5.1), past = grid.band(5.7);
  EXPECT_NE(before, past);
  EXPECT_DOUBLE_EQ(grid.from_m(before), 5.0);
  EXPECT_DOUBLE_EQ(grid.to_m(before), 5.5);
  EXPECT_DOUBLE_EQ(grid.from_m(past), 5.5);
  EXPECT_DOUBLE_EQ(grid.to_m(past), 6.0);
  EXPECT_EQ(grid.band(5.5), past);
  EXPECT_EQ(grid.band(5.0), before);
  // A plate on a cell's edge cuts nothing: the cells either side are whole.
  EXPECT_DOUBLE_EQ(grid.from_m(grid.band(2.4)), 2.0);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(2.4)), 3.0);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(1.9)), 2.0);
  EXPECT_DOUBLE_EQ(grid.centre_m(grid.band(7.2)), 7.5);
}

TEST(WallBandGrid, APieceShorterThanHalfABandJoinsTheBandBesideIt) {
  const WallBandGrid grid(1.0, {5.3, 8.8});
  // 5.0-5.3 joins 4-5; 8.8-9.0 joins 9-10; 5.3-6 and 8-8.8 stay bands of their own.
  EXPECT_EQ(grid.band(5.1), grid.band(4.5));
  EXPECT_DOUBLE_EQ(grid.from_m(grid.band(5.1)), 4.0);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(5.1)), 5.3);
  EXPECT_DOUBLE_EQ(grid.from_m(grid.band(5.5)), 5.3);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(5.5)), 6.0);
  EXPECT_EQ(grid.band(8.9), grid.band(9.5));
  EXPECT_DOUBLE_EQ(grid.from_m(grid.band(9.5)), 8.8);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(9.5)), 10.0);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(8.5)), 8.8);
  // A plate on the edge of the next cell keeps a piece from joining across it.
  const WallBandGrid edge(1.0, {2.7, 3.0});
  EXPECT_DOUBLE_EQ(edge.from_m(edge.band(2.8)), 2.7);
  EXPECT_DOUBLE_EQ(edge.to_m(edge.band(2.8)), 3.0);
  EXPECT_DOUBLE_EQ(edge.from_m(edge.band(3.5)), 3.0);
  // Every station lies in its band.
  for (double s = 3.0; s < 11.0; s += 0.01) {
    const long band = grid.band(s);
    EXPECT_LE(grid.from_m(band), s + 1e-12) << s;
    EXPECT_GT(grid.to_m(band), s) << s;
  }
}

TEST(WallBandGrid, OrdersBandsAlongTheGirderBehindTheStartToo) {
  const WallBandGrid grid(0.5, {-0.8});
  double last_from = -10.0;
  for (double s = -2.0; s < 2.0; s += 0.05) {
    const long band = grid.band(s);
    EXPECT_LE(grid.from_m(band), s + 1e-12) << s;
    EXPECT_GT(grid.to_m(band), s) << s;
    EXPECT_GE(grid.from_m(band), last_from) << s;
    last_from = grid.from_m(band);
  }
  EXPECT_LT(grid.band(-0.9), grid.band(-0.7));
  EXPECT_DOUBLE_EQ(grid.from_m(grid.band(-0.7)), -0.8);
  EXPECT_DOUBLE_EQ(grid.to_m(grid.band(-0.9)), -0.8);
}

TEST(WallBandGrid, TellsWhetherAPlateLiesBetweenTwoBands) {
  const WallBandGrid grid(1.0, {5.3});
  EXPECT_TRUE(grid.plate_between(grid.band(5.1), grid.band(5.6)));
  EXPECT_TRUE(grid.plate_between(grid.band(4.5), grid.band(5.6)));  // 4-5.3 and 5.3-6
  EXPECT_TRUE(grid.plate_between(grid.band(7.5), grid.band(3.5)));
  EXPECT_FALSE(grid.plate_between(grid.band(3.5), grid.band(4.5)));
  EXPECT_FALSE(grid.plate_between(grid.band(4.5), grid.band(5.1)));  // one band
  EXPECT_FALSE(grid.plate_between(grid.band(5.6), grid.band(6.5)));
}

}  // namespace
}  // namespace tunnelmap
