#pragma once
// The median of the finite values (NaN marks "not measured"); NaN when there are none.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace tunnelmap {

inline double median_of_measured(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = v.size();
  std::nth_element(v.begin(), v.begin() + n / 2, v.end());
  const double upper = v[n / 2];
  if (n % 2) return upper;
  return 0.5 * (*std::max_element(v.begin(), v.begin() + n / 2) + upper);
}

}  // namespace tunnelmap
