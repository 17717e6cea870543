#include "core/mapping/end_wall_trim.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace tunnelmap {

namespace {

bool measured(const Station& st) {
  return st.width_source == DimensionSource::Measured || st.height_source == DimensionSource::Measured;
}

// The stretch between the end walls (unbounded on a side without one). The first plate bounds
// the girder before it, the last after it, as they were found to end it; a lone end wall bounds
// the side fewer measured stations lie on (the girder is where the walk measured it).
std::array<double, 2> girder_extent(const StationMap& map) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::array<double, 2> extent{-kInf, kInf};
  const std::vector<Diaphragm>& plates = map.girder.diaphragms;
  if (plates.empty()) return extent;
  if (plates.size() > 1) {
    if (plates.front().kind == "end_wall") extent[0] = plates.front().station_m;
    if (plates.back().kind == "end_wall") extent[1] = plates.back().station_m;
    return extent;
  }
  if (plates.front().kind != "end_wall") return extent;
  const double s = plates.front().station_m;
  long before = 0, after = 0;
  for (const Station& st : map.stations)
    if (measured(st)) (st.station_m > s ? after : before) += 1;
  extent[after > before ? 0 : 1] = s;
  return extent;
}

}  // namespace

bool trim_beyond_end_walls(StationMap& map, std::vector<std::array<double, 4>>& section_walls) {
  if (section_walls.size() != map.sections.size())
    throw std::logic_error("trim_beyond_end_walls: one wall entry per section expected");
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
    if (sections.empty()) s.joint_seen = true, s.joint_uncertainty_m = 0.0;  // the first has no joint
    sections.push_back(s);
    walls.push_back(section_walls[i]);
  }
  map.sections = std::move(sections);
  section_walls = std::move(walls);
  return true;
}

}  // namespace tunnelmap
