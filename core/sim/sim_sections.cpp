#include "core/sim/sim_sections.h"

#include <functional>

#include <algorithm>
#include <limits>

namespace tunnelmap::sim {

SimSections::SimSections(const SimConfig& c) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (c.sections.empty()) {
    spans_.push_back({-kInf, kInf, c.width_m, c.height_m});
    return;
  }
  double x = c.sections_start_x_m;
  for (const SimSection& s : c.sections) {
    spans_.push_back({x, x + s.length_m, s.width_m, s.height_m});
    x += s.length_m;
  }
  spans_.front().from_x = -kInf;
  spans_.back().to_x = kInf;
}

int SimSections::index_at(double x) const {
  // First span whose end is beyond x (spans are contiguous and sorted).
  const auto it = std::upper_bound(spans_.begin(), spans_.end() - 1, x,
                                   [](double v, const SimSpan& s) { return v < s.to_x; });
  return static_cast<int>(it - spans_.begin());
}

std::vector<double> SimSections::joints_x() const {
  std::vector<double> x;
  for (std::size_t k = 1; k < spans_.size(); ++k) x.push_back(spans_[k].from_x);
  return x;
}

namespace {
// The smallest (`less`) or largest value of `field` over the spans.
template <typename Better>
double extreme(const std::vector<SimSpan>& spans, double SimSpan::*field, Better better) {
  double v = spans[0].*field;
  for (const SimSpan& s : spans)
    if (better(s.*field, v)) v = s.*field;
  return v;
}
}  // namespace

double SimSections::min_width() const { return extreme(spans_, &SimSpan::width_m, std::less<>()); }
double SimSections::min_height() const { return extreme(spans_, &SimSpan::height_m, std::less<>()); }
double SimSections::max_width() const { return extreme(spans_, &SimSpan::width_m, std::greater<>()); }
double SimSections::max_height() const { return extreme(spans_, &SimSpan::height_m, std::greater<>()); }

}  // namespace tunnelmap::sim
