#include "core/report/statistics.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap {

MeanSigma mean_sigma(const double* v, std::size_t n) {
  MeanSigma s;
  s.n = static_cast<int>(n);
  if (n == 0) return s;
  for (std::size_t i = 0; i < n; ++i) s.mean += v[i];
  s.mean /= static_cast<double>(n);
  if (n < 2) return s;
  // Two passes: the sum of squared deviations does not cancel like sum(x^2) - n*mean^2 does.
  double ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) ss += (v[i] - s.mean) * (v[i] - s.mean);
  s.sigma = std::sqrt(ss / static_cast<double>(n - 1));
  return s;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

double mean_abs_error(const std::vector<double>& values, double truth) {
  if (values.empty()) return 0.0;
  double s = 0.0;
  for (double x : values) s += std::abs(x - truth);
  return s / static_cast<double>(values.size());
}

}  // namespace tunnelmap
