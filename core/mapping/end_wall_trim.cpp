#include "core/mapping/end_wall_trim.h"

#include <algorithm>
#include <limits>

namespace tunnelmap {

namespace {

// The stretch between the end walls (unbounded on a side without one). An end wall bounds the
// side fewer stations lie on: the girder is where the walk measured it.
std::array<double, 2> girder_extent(const StationMap& map) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::array<double, 2> extent{-kInf, kInf};
  for (const Diaphragm& d : map.girder.diaphragms) {
    if (d.kind != "end_wall") continue;
    const auto after = std::count_if(map.stations.begin(), map.stations.end(),
                                     [&](const Station& st) { return st.station_m > d.station_m; });
    const bool girder_after = 2 * after > static_cast<long>(map.stations.size());
    if (girder_after)
      extent[0] = std::max(extent[0], d.station_m);
    else
      extent[1] = std::min(extent[1], d.station_m);
  }
  return extent;
}

}  // namespace

bool trim_beyond_end_walls(StationMap& map, std::vector<std::array<double, 4>>& section_walls) {
  const std::array<double, 2> extent = girder_extent(map);
  const double half = 0.5 * map.options.station_step_m;
  const auto inside = [&](const Station& st) {
    return st.station_m + half > extent[0] && st.station_m - half < extent[1];
  };
  const std::size_t before = map.stations.size();
  map.stations.erase(std::remove_if(map.stations.begin(), map.stations.end(),
                                    [&](const Station& st) { return !inside(st); }),
                     map.stations.end());
  if (map.stations.size() == before || map.stations.empty()) return map.stations.size() != before;
  const double from = map.stations.front().station_m - half, to = map.stations.back().station_m + half;
  std::vector<Section> sections;
  std::vector<std::array<double, 4>> walls;
  for (std::size_t i = 0; i < map.sections.size(); ++i) {
    Section s = map.sections[i];
    s.from_m = std::max(s.from_m, from);
    s.to_m = std::min(s.to_m, to);
    if (s.to_m - s.from_m < half) continue;  // wholly beyond
    sections.push_back(s);
    if (i < section_walls.size()) walls.push_back(section_walls[i]);
  }
  map.sections = std::move(sections);
  section_walls = std::move(walls);
  return true;
}

}  // namespace tunnelmap
