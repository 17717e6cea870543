#include "ui/report/report_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap::report {

double nice_step(double span, int max_ticks) {
  if (!(span > 0.0) || max_ticks < 1) return 1.0;
  const double raw = span / max_ticks;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw * (1.0 - 1e-9)) return m * mag;
  return 10.0 * mag;
}

std::vector<double> ticks(double lo, double hi, double step) {
  std::vector<double> out;
  if (!(step > 0.0) || !(hi >= lo)) return out;
  const double eps = step * 1e-6;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps && out.size() < 1000; k += 1.0)
    out.push_back(k * step);
  return out;
}

int decimals_for(double step) {
  int d = 0;
  while (d < 6 && std::abs(step * std::pow(10.0, d) - std::round(step * std::pow(10.0, d))) > 1e-6) ++d;
  return d;
}

void station_range(const StationMap& map, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  const double half = 0.5 * map.options.station_step_m;
  for (const Station& s : map.stations) {
    lo = std::min(lo, s.station_m - half);
    hi = std::max(hi, s.station_m + half);
  }
  for (const Section& s : map.sections) {
    lo = std::min(lo, s.from_m);
    hi = std::max(hi, s.to_m);
  }
  for (const PoseGroupStatus& pose : map.poses) {
    const double s = map.station_of(pose.camera_to_world.translation());
    if (std::isfinite(s)) {
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  }
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (hi - lo < 0.5) {  // at least half a metre, centred
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.25;
    hi = mid + 0.25;
  }
}

}  // namespace tunnelmap::report
