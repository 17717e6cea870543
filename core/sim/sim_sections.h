#pragma once
// SimSections: the cross-section of the simulated tunnel along its axis (world X). Without
// SimConfig::sections it is one span of width_m x height_m from -inf to +inf; otherwise one
// span per section, the first reaching back to -inf and the last on to +inf.
#include <vector>

#include "core/sim/sim_config.h"

namespace tunnelmap::sim {

struct SimSpan {
  double from_x, to_x;  // [from_x, to_x); -inf / +inf at the ends
  double width_m, height_m;
};

class SimSections {
 public:
  explicit SimSections(const SimConfig& config);

  const std::vector<SimSpan>& spans() const { return spans_; }
  int index_at(double x) const;  // a joint's x belongs to the section after it
  const SimSpan& at(double x) const { return spans_[index_at(x)]; }
  std::vector<double> joints_x() const;  // where one section meets the next, in order
  double min_width() const;
  double min_height() const;
  double max_width() const;
  double max_height() const;

 private:
  std::vector<SimSpan> spans_;
};

}  // namespace tunnelmap::sim
