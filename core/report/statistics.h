#pragma once
// The one place where TunnelMap's outputs are averaged: the CLI summaries (`detect`), the
// evaluation's Table 1 cells and the GUI's results panel all use these functions.
#include <cstddef>
#include <vector>

namespace tunnelmap {

struct MeanSigma {
  int n = 0;
  double mean = 0.0;
  // Sample standard deviation (divides by n - 1), as in the paper's Table 1; 0 for n < 2.
  double sigma = 0.0;
};

MeanSigma mean_sigma(const double* values, std::size_t n);
inline MeanSigma mean_sigma(const std::vector<double>& v) { return mean_sigma(v.data(), v.size()); }

// Median (mean of the two middle values for an even count); 0 for no values.
double median(std::vector<double> values);

// Mean of |v - truth|; 0 for no values.
double mean_abs_error(const std::vector<double>& values, double truth);

}  // namespace tunnelmap
