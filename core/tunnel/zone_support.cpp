#include "core/tunnel/zone_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.h"

namespace tunnelmap {

int ZoneScaling::support_at(double distance_m) const {
  // Off, or at/inside the reference distance: the configured support, bit for bit.
  if (!(support_ref_m > 0) || !(distance_m > support_ref_m)) return min_points;
  const double ratio = support_ref_m / distance_m;
  const double scaled = std::ceil(min_points * ratio * ratio);
  return std::min(min_points, std::max(kMinScaledZoneSupport, static_cast<int>(scaled)));
}

double ZoneScaling::gap_at(double distance_m) const {
  if (!(gap_ref_m > 0) || !(distance_m > gap_ref_m)) return gap_m;
  const double ratio = distance_m / gap_ref_m;
  return gap_m * ratio * ratio;
}

void check_zone_scaling(const ZoneScaling& s) {
  const auto bad = [](double v) { return !std::isfinite(v) || v < 0; };
  char msg[160];
  if (bad(s.support_ref_m) || bad(s.gap_ref_m) || !(s.gap_m > 0) || s.min_points < 0) {
    std::snprintf(msg, sizeof msg,
                  "tunnel options: zone support ref %g m, gap ref %g m, gap %g m and support %d "
                  "points must be finite and >= 0 (gap > 0)",
                  s.support_ref_m, s.gap_ref_m, s.gap_m, s.min_points);
    throw ParameterError(msg);
  }
}

}  // namespace tunnelmap
