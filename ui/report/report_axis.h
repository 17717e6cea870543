#pragma once
// Linear axes of the plan and the plots: value <-> page coordinate, and "nice" tick steps
// (1, 2, 5 x 10^n) so the labels read as round numbers.
#include <QString>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap::report {

struct Axis {
  double lo = 0.0, hi = 1.0;    // value range
  double p0 = 0.0, p1 = 1.0;    // page coordinates of lo and hi (p1 < p0 for a y axis)
  double at(double v) const { return p0 + (v - lo) / (hi - lo) * (p1 - p0); }
};

// The smallest 1/2/5 x 10^n step giving at most `max_ticks` intervals over `span`.
double nice_step(double span, int max_ticks);
// Multiples of `step` within [lo, hi].
std::vector<double> ticks(double lo, double hi, double step);
// Decimals needed to print multiples of `step` exactly (0 for >= 1, 1 for 0.5, 3 for 0.001).
int decimals_for(double step);

// Station range the plan and plots share: every station's bin, every section and every pose's
// camera, widened so that a one-station map still has a width.
void station_range(const StationMap& map, double& lo, double& hi);

}  // namespace tunnelmap::report
