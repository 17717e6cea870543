#include "core/mapping/rescan_stretches.h"

#include <algorithm>

namespace tunnelmap {

namespace {

bool unmeasured(const Station& s, StationDimension d) {
  return (d == StationDimension::Width ? s.width_source : s.height_source) != DimensionSource::Measured;
}

// A joint placed between views, at `from_m` of a section after the first, lies in [from, to].
bool hidden_joint_in(const StationMap& m, double from_m, double to_m) {
  for (std::size_t i = 1; i < m.sections.size(); ++i) {
    const Section& s = m.sections[i];
    if (!s.joint_seen && s.from_m >= from_m - 1e-9 && s.from_m <= to_m + 1e-9) return true;
  }
  return false;
}

RescanStretch stretch_of(const StationMap& m, StationDimension d, std::size_t first, std::size_t last) {
  const double half = 0.5 * m.options.station_step_m;
  RescanStretch r;
  r.dimension = d;
  r.from_m = m.stations[first].station_m - half;
  r.to_m = m.stations[last].station_m + half;
  r.joint_inside = hidden_joint_in(m, r.from_m, r.to_m);
  r.reason = std::string("no frame measured the ") + station_dimension_name(d) + " here";
  if (r.joint_inside) r.reason += "; a joint lies somewhere in this stretch";
  return r;
}

void add_stretches(const StationMap& m, StationDimension d, std::vector<RescanStretch>& out) {
  // A shorter stretch cannot hide a section (map.min_section_m makes the same cut).
  const double shortest = m.options.min_section_stations * m.options.station_step_m;
  const std::size_t n = m.stations.size();
  for (std::size_t k = 0; k < n;) {
    if (!unmeasured(m.stations[k], d)) {
      ++k;
      continue;
    }
    std::size_t last = k;
    while (last + 1 < n && unmeasured(m.stations[last + 1], d)) ++last;
    const RescanStretch r = stretch_of(m, d, k, last);
    if (r.joint_inside || r.to_m - r.from_m >= shortest - 1e-9) out.push_back(r);
    k = last + 1;
  }
}

}  // namespace

const char* station_dimension_name(StationDimension d) { return d == StationDimension::Width ? "width" : "height"; }

std::vector<RescanStretch> rescan_stretches(const StationMap& m) {
  std::vector<RescanStretch> out;
  add_stretches(m, StationDimension::Width, out);
  add_stretches(m, StationDimension::Height, out);
  std::stable_sort(out.begin(), out.end(),
                   [](const RescanStretch& a, const RescanStretch& b) { return a.from_m < b.from_m; });
  return out;
}

}  // namespace tunnelmap
