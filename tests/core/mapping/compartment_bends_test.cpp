#include "core/mapping/compartment_bends.h"

#include <gtest/gtest.h>

namespace tunnelmap {
namespace {

// Bands 1 m long of one kind from 0 to `to_m`, band b on plane 100 (kind + 1) + b.
std::vector<WallBand> bands_of_kind(int kind, long to_m) {
  std::vector<WallBand> bands;
  for (long b = 0; b < to_m; ++b)
    bands.push_back({kind, static_cast<double>(b), static_cast<double>(b + 1), 100 * (kind + 1) + static_cast<int>(b)});
  return bands;
}

TEST(CompartmentBends, TiesTheWholeBandsOfEveryThreeNeighbouringCompartments) {
  // Plates at 3.5, 7.5, 11.5 and 15.5 m: the compartments between hold bands 4-6, 8-10 and
  // 12-14 whole (3, 7, 11 and 15 hold a plate), at 5.5, 9.5 and 13.5 m.
  const std::vector<PlaneBend> ties = compartment_bends(bands_of_kind(0, 18), {15.5, 3.5, 11.5, 7.5}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].a, (std::vector<int>{104, 105, 106}));
  EXPECT_EQ(ties[0].b, (std::vector<int>{108, 109, 110}));
  EXPECT_EQ(ties[0].c, (std::vector<int>{112, 113, 114}));
  EXPECT_DOUBLE_EQ(ties[0].weight_a, 0.5);
  EXPECT_DOUBLE_EQ(ties[0].weight_c, 0.5);
  EXPECT_DOUBLE_EQ(ties[0].sigma_rad, 0.001);
}

TEST(CompartmentBends, WeighsByWhereEachCompartmentsBandsLie) {
  // Plates at 1, 3, 7 and 13 m, each where a band begins: the compartments hold bands 1-2, 3-6
  // and 7-12, at 2, 5 and 10 m: the middle one lies 3/8 of the way.
  const std::vector<PlaneBend> ties = compartment_bends(bands_of_kind(0, 14), {1.0, 3.0, 7.0, 13.0}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].a, (std::vector<int>{101, 102}));
  EXPECT_EQ(ties[0].b, (std::vector<int>{103, 104, 105, 106}));
  EXPECT_DOUBLE_EQ(ties[0].weight_c, 3.0 / 8.0);
  EXPECT_DOUBLE_EQ(ties[0].weight_a, 5.0 / 8.0);
}

TEST(CompartmentBends, EachKindOfWallIsTiedToItselfAndACompartmentNotSeenBreaksTheChain) {
  std::vector<WallBand> bands = bands_of_kind(0, 18);
  for (const WallBand& b : bands_of_kind(1, 18))
    if (b.from_m < 8.0 || b.from_m > 10.0) bands.push_back(b);  // kind 1 unseen in the second compartment
  const std::vector<PlaneBend> ties = compartment_bends(bands, {3.5, 7.5, 11.5, 15.5}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].b, (std::vector<int>{108, 109, 110}));  // kind 0's only
}

TEST(CompartmentBends, NoThreeCompartmentsNoTies) {
  EXPECT_TRUE(compartment_bends(bands_of_kind(0, 18), {}, 0.001).empty());
  EXPECT_TRUE(compartment_bends(bands_of_kind(0, 18), {4.0, 8.0, 12.0}, 0.001).empty());  // two compartments
}

}  // namespace
}  // namespace tunnelmap
