// The one mean/sigma of the results (CLI summary, evaluation cells, GUI panel): sample sigma,
// checked against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/pipeline/pipeline.h"
#include "core/report/results_json.h"
#include "core/report/statistics.h"

using namespace tunnelmap;

TEST(Statistics, SampleSigmaOfAHandComputedExample) {
  // 2 4 4 4 5 5 7 9: mean 5, squared deviations 9+1+1+1+0+0+4+16 = 32, n - 1 = 7.
  const MeanSigma s = mean_sigma(std::vector<double>{2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(s.n, 8);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.sigma, std::sqrt(32.0 / 7.0), 1e-12);  // 2.13809; the population sigma is 2
  EXPECT_NEAR(s.sigma, 2.1380899353, 1e-9);
}

TEST(Statistics, WidthsInMetresKeepTheirPrecision) {
  // The lab sample's three widths (`detect resources/sample/lab`), to a tenth of a millimetre.
  const MeanSigma s = mean_sigma(std::vector<double>{0.8059, 0.8044, 0.8058});
  EXPECT_NEAR(s.mean, 0.805366666667, 1e-12);
  // deviations 0.533, -0.967, 0.433 (x 1e-3): squares sum 1.4067e-6, / 2 -> sigma 0.8386e-3
  EXPECT_NEAR(s.sigma, 0.000838650, 1e-9);
}

TEST(Statistics, FewValues) {
  EXPECT_EQ(mean_sigma(std::vector<double>{}).n, 0);
  EXPECT_EQ(mean_sigma(std::vector<double>{}).mean, 0.0);
  const MeanSigma one = mean_sigma(std::vector<double>{1.25});
  EXPECT_EQ(one.mean, 1.25);
  EXPECT_EQ(one.sigma, 0.0);  // undefined for one value: reported as 0
  EXPECT_NEAR(mean_sigma(std::vector<double>{1.0, 2.0}).sigma, std::sqrt(0.5), 1e-12);
}

TEST(Statistics, MedianAndMeanAbsError) {
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(median({3, 1, 2}), 2.0);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_NEAR(mean_abs_error({0.79, 0.81, 0.83}, 0.80), (0.01 + 0.01 + 0.03) / 3, 1e-12);
  EXPECT_EQ(mean_abs_error({}, 0.8), 0.0);
}

TEST(Statistics, DetectionSummaryUsesTheSampleSigmaOfMeasuredValues) {
  DetectionSummary summary;
  summary.gt_width_m = 0.80;
  for (double w : {0.79, 0.80, 0.84}) {
    FrameResult r;
    r.map.detected = true;
    r.map.status = TunnelStatus::Ok;
    r.map.width_m = w;
    r.map.height_m = 1.2;
    r.map.width_source = r.map.height_source = DimensionSource::Measured;
    r.timings_ms["total"] = 10.0;
    summary.add(r);
  }
  FrameResult partial;  // an inferred width is the context's, not a measurement
  partial.map.detected = true;
  partial.map.status = TunnelStatus::Partial;
  partial.map.width_m = 0.5;
  partial.map.width_source = DimensionSource::Context;
  partial.map.height_m = 1.2;
  partial.map.height_source = DimensionSource::Measured;
  summary.add(partial);
  summary.finish();
  EXPECT_EQ(summary.detected, 4);
  EXPECT_EQ(summary.partial, 1);
  // mean 0.81, deviations -0.02 -0.01 0.03: (4e-4 + 1e-4 + 9e-4) / 2 = 7e-4 -> sigma 0.026458
  EXPECT_EQ(summary.width_frames, 3);
  EXPECT_EQ(summary.height_frames, 4);
  EXPECT_NEAR(summary.width_mean_m.value(), 0.81, 1e-12);
  EXPECT_NEAR(summary.width_std_m.value(), std::sqrt(7e-4), 1e-12);
  EXPECT_NEAR(summary.height_std_m.value(), 0.0, 1e-12);
  EXPECT_NEAR(summary.width_abs_error_mean_m.value(), (0.01 + 0.0 + 0.04) / 3, 1e-12);
}
