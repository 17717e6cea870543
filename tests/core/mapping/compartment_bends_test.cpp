#include "core/mapping/compartment_bends.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tunnelmap {
namespace {

// Bands 1 m long of one kind from 0 to `to_m`, band b on plane 100 (kind + 1) + b.
std::vector<WallBand> bands_of_kind(int kind, long to_m) {
  std::vector<WallBand> bands;
  for (long b = 0; b < to_m; ++b)
    bands.push_back({kind, static_cast<double>(b), static_cast<double>(b + 1), 100 * (kind + 1) + static_cast<int>(b)});
  return bands;
}

TEST(CompartmentBends, TiesTheWholeBandsOfEveryFourNeighbouringCompartments) {
  // Plates at 3.5, 7.5, 11.5, 15.5 and 19.5 m: the compartments between hold bands 4-6, 8-10,
  // 12-14 and 16-18 whole (3, 7, 11, 15 and 19 hold a plate), at 5.5, 9.5, 13.5 and 17.5 m.
  // Evenly spaced, the second lies on the quadratic through the others with weights 1/3, 1
  // and -1/3.
  const std::vector<PlaneBend> ties = compartment_bends(bands_of_kind(0, 22), {15.5, 3.5, 19.5, 11.5, 7.5}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  ASSERT_EQ(ties[0].stretches.size(), 4u);
  EXPECT_EQ(ties[0].stretches[0], (std::vector<int>{104, 105, 106}));
  EXPECT_EQ(ties[0].stretches[1], (std::vector<int>{108, 109, 110}));
  EXPECT_EQ(ties[0].stretches[2], (std::vector<int>{112, 113, 114}));
  EXPECT_EQ(ties[0].stretches[3], (std::vector<int>{116, 117, 118}));
  ASSERT_EQ(ties[0].weights.size(), 4u);
  EXPECT_NEAR(ties[0].weights[0], -1.0 / 3.0, 1e-12);
  EXPECT_NEAR(ties[0].weights[1], 1.0, 1e-12);
  EXPECT_NEAR(ties[0].weights[2], -1.0, 1e-12);
  EXPECT_NEAR(ties[0].weights[3], 1.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(ties[0].sigma_rad, 0.001);
}

// The tie's weighted sum of the directions of a wall whose heading is h(s) at each
// compartment's station.
double tie_residual(const PlaneBend& tie, const std::vector<double>& stations, double (*heading)(double)) {
  double sum = 0.0;
  for (std::size_t k = 0; k < tie.weights.size(); ++k) sum += tie.weights[k] * heading(stations[k]);
  return sum;
}

TEST(CompartmentBends, AnUnevenSpacingStillLeavesAnyEvenChangeOfCurvatureUntied) {
  // Plates at 1, 3, 7, 13 and 14 m, each where a band begins: the compartments hold bands 1-2,
  // 3-6, 7-12 and 13, at 2, 5, 10 and 13.5 m. A heading that is a quadratic in the station (a
  // transition curve) leaves the tie at zero; one that is cubic does not.
  const std::vector<PlaneBend> ties = compartment_bends(bands_of_kind(0, 16), {1.0, 3.0, 7.0, 13.0, 14.0}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].stretches[0], (std::vector<int>{101, 102}));
  EXPECT_EQ(ties[0].stretches[1], (std::vector<int>{103, 104, 105, 106}));
  EXPECT_EQ(ties[0].stretches[3], (std::vector<int>{113}));
  const std::vector<double> at = {2.0, 5.0, 10.0, 13.5};
  double weight_sum = 0.0;
  for (double w : ties[0].weights) weight_sum += w;
  EXPECT_NEAR(weight_sum, 0.0, 1e-12);
  EXPECT_NEAR(tie_residual(ties[0], at, [](double s) { return 0.01 + 0.002 * s + 3e-4 * s * s; }), 0.0, 1e-12);
  EXPECT_GT(std::abs(tie_residual(ties[0], at, [](double s) { return 1e-4 * s * s * s; })), 1e-3);
}

TEST(CompartmentBends, EachKindOfWallIsTiedToItselfAndACompartmentNotSeenBreaksTheChain) {
  std::vector<WallBand> bands = bands_of_kind(0, 22);
  for (const WallBand& b : bands_of_kind(1, 22))
    if (b.from_m < 8.0 || b.from_m > 10.0) bands.push_back(b);  // kind 1 unseen in the second compartment
  const std::vector<PlaneBend> ties = compartment_bends(bands, {3.5, 7.5, 11.5, 15.5, 19.5}, 0.001);
  ASSERT_EQ(ties.size(), 1u);
  EXPECT_EQ(ties[0].stretches[1], (std::vector<int>{108, 109, 110}));  // kind 0's only
}

TEST(CompartmentBends, AnEvenTurnPutsTheMiddleOfThreeCompartmentsBetweenTheOthers) {
  // Plates at 1, 3, 7 and 13 m, each where a band begins: the compartments hold bands 1-2, 3-6
  // and 7-12, at 2, 5 and 10 m: the middle one lies 3/8 of the way.
  const std::vector<std::vector<EvenTurn>> turns = compartment_even_turns(bands_of_kind(0, 14), {1.0, 3.0, 7.0, 13.0}, 0.001);
  ASSERT_EQ(turns.size(), 1u);
  ASSERT_EQ(turns[0].size(), 1u);
  EXPECT_EQ(turns[0][0].compartment, 2);
  const PlaneBend& t = turns[0][0].tie;
  EXPECT_EQ(t.stretches[0], (std::vector<int>{101, 102}));
  EXPECT_EQ(t.stretches[1], (std::vector<int>{103, 104, 105, 106}));
  ASSERT_EQ(t.weights.size(), 3u);
  EXPECT_DOUBLE_EQ(t.weights[0], -5.0 / 8.0);
  EXPECT_DOUBLE_EQ(t.weights[1], 1.0);
  EXPECT_DOUBLE_EQ(t.weights[2], -3.0 / 8.0);
}

// Planes 100 + b of a wall whose heading at band b's middle (b + 0.5 m) is heading(b + 0.5).
std::vector<GraphPlane> wall_heading(long bands, double (*heading)(double)) {
  std::vector<GraphPlane> planes(static_cast<std::size_t>(100 + bands));
  for (long b = 0; b < bands; ++b) {
    const double t = heading(b + 0.5);
    planes[static_cast<std::size_t>(100 + b)] = {Eigen::Vector3d(-std::sin(t), std::cos(t), 0.0), 0.0};
  }
  return planes;
}

TEST(CompartmentBends, TheEvenTurnIsTiedWhereTheMapTurnsEvenlyAndNotAlongATransition) {
  // Plates every 4 m from 3.5 to 39.5 m: nine compartments, seven even turns, tolerance 0.01
  // degrees. A circular arc of 150 m with a wander of 0.002 degrees keeps them all (its even
  // turns depart by 0.02 degrees along the normal, which does not count); a transition curve
  // (the heading grows as x^2 / (2 R L), R 150 m, L 57 m: 0.054 degrees off an even turn at
  // every plate) keeps none; a transition over the last part keeps those before it.
  std::vector<double> plates;
  for (double x = 3.5; x < 40.0; x += 4.0) plates.push_back(x);
  const double sigma = 0.01 * M_PI / 180.0;
  const std::vector<std::vector<EvenTurn>> turns = compartment_even_turns(bands_of_kind(0, 44), plates, sigma);
  ASSERT_EQ(turns.size(), 1u);
  ASSERT_EQ(turns[0].size(), 7u);
  const auto arc = [](double x) { return x / 150.0 + 0.002 * M_PI / 180.0 * std::sin(2.0 * x); };
  const auto transition = [](double x) { return x * x / (2.0 * 150.0 * 57.0); };
  const auto late = [](double x) { return x < 25.5 ? 0.0 : (x - 25.5) * (x - 25.5) / (2.0 * 150.0 * 57.0); };
  EXPECT_EQ(even_turns_where_the_map_turns_evenly(turns, wall_heading(44, arc)).size(), 7u);
  EXPECT_TRUE(even_turns_where_the_map_turns_evenly(turns, wall_heading(44, transition)).empty());
  const std::vector<PlaneBend> kept = even_turns_where_the_map_turns_evenly(turns, wall_heading(44, late));
  ASSERT_FALSE(kept.empty());
  EXPECT_LT(kept.size(), 7u);
  EXPECT_EQ(kept[0].stretches[1], turns[0][0].tie.stretches[1]);
}

TEST(CompartmentBends, AnEvenTurnsNeighbourhoodDoesNotReachPastACompartmentNoFrameSaw) {
  // Plates every 4 m from 3.5 to 39.5 m; no wall seen between 15.5 and 19.5 m (compartment 4).
  // The even turns left are those about compartments 2, 6, 7 and 8. A transition from 21.5 m on
  // puts 6, 7 and 8 0.054 degrees off an even turn; compartment 2, on the straight, keeps its
  // tie: its neighbourhood (two compartments either side) holds no other turn. Counted by
  // place in the list it held those about 6 and 7, beyond the gap, and lost it.
  std::vector<double> plates;
  for (double x = 3.5; x < 40.0; x += 4.0) plates.push_back(x);
  std::vector<WallBand> bands;
  for (const WallBand& b : bands_of_kind(0, 44))
    if (b.from_m < 16.0 || b.from_m > 18.0) bands.push_back(b);
  const double sigma = 0.01 * M_PI / 180.0;
  const std::vector<std::vector<EvenTurn>> turns = compartment_even_turns(bands, plates, sigma);
  ASSERT_EQ(turns.size(), 1u);
  std::vector<int> middles;
  for (const EvenTurn& t : turns[0]) middles.push_back(t.compartment);
  EXPECT_EQ(middles, (std::vector<int>{2, 6, 7, 8}));
  const auto late = [](double x) { return x < 21.5 ? 0.0 : (x - 21.5) * (x - 21.5) / (2.0 * 150.0 * 57.0); };
  const std::vector<PlaneBend> kept = even_turns_where_the_map_turns_evenly(turns, wall_heading(44, late));
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].stretches[1], turns[0][0].tie.stretches[1]);
}

TEST(CompartmentBends, NoFourCompartmentsNoTies) {
  EXPECT_TRUE(compartment_bends(bands_of_kind(0, 18), {}, 0.001).empty());
  EXPECT_TRUE(compartment_bends(bands_of_kind(0, 18), {3.5, 7.5, 11.5, 15.5}, 0.001).empty());  // three compartments
}

}  // namespace
}  // namespace tunnelmap
