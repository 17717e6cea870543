// The evidence test that decides whether a pose graph's optimum may replace the given poses.
#include "core/solvers/correction_evidence.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tunnelmap {
namespace {

TEST(CorrectionEvidence, ADropWithinTheNoiseKeepsTheGivenPoses) {
  // 119 free poses: 714 degrees of freedom, so noise alone gives a chi-square gain of about 714
  // with a standard deviation of sqrt(1428) = 37.8.
  const CorrectionEvidence e = correction_evidence(98.5, 88.7, 119, 3.0);
  EXPECT_EQ(e.dof, 714);
  EXPECT_NEAR(e.chi2_gain, 19.6, 1e-9);
  EXPECT_NEAR(e.threshold, 714.0 + 3.0 * std::sqrt(1428.0), 1e-9);
  EXPECT_FALSE(e.significant);
}

TEST(CorrectionEvidence, ADropFarBeyondTheNoiseIsAPoseError) {
  const CorrectionEvidence e = correction_evidence(7445.6, 356.4, 119, 3.0);
  EXPECT_NEAR(e.chi2_gain, 14178.4, 1e-6);
  EXPECT_TRUE(e.significant);
}

TEST(CorrectionEvidence, TheThresholdIsOnTheEdge) {
  const double threshold = 12.0 + 2.0 * std::sqrt(24.0);
  EXPECT_FALSE(correction_evidence(threshold / 2.0, 0.0, 2, 2.0).significant);
  EXPECT_TRUE(correction_evidence(threshold / 2.0 + 1e-6, 0.0, 2, 2.0).significant);
}

TEST(CorrectionEvidence, ZeroSigmasAlwaysCorrectsUnlessNothingIsFree) {
  EXPECT_TRUE(correction_evidence(1.0, 1.0, 5, 0.0).significant);
  EXPECT_FALSE(correction_evidence(1.0, 0.0, 0, 0.0).significant);
}

TEST(CorrectionEvidence, ACostThatRoseIsNoGain) {
  // A solver that stopped above the given poses' cost has found nothing.
  const CorrectionEvidence e = correction_evidence(10.0, 12.0, 3, 3.0);
  EXPECT_EQ(e.chi2_gain, 0.0);
  EXPECT_FALSE(e.significant);
}

}  // namespace
}  // namespace tunnelmap
