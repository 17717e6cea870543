#include "core/mapping/station_frames.h"

#include <algorithm>

#include <cmath>
#include <limits>

namespace tunnelmap {

std::optional<StationView> frame_for_station(const StationMap& map, const std::vector<Eigen::Isometry3d>& poses,
                                             const std::vector<bool>& detected, double station_m,
                                             double preferred_ahead_m, double max_ahead_m) {
  std::optional<StationView> best;
  double best_cost = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    if (i < detected.size() && !detected[i]) continue;
    const Eigen::Vector3d eye = poses[i].translation();
    const Eigen::Vector3d forward = poses[i].linear().col(2);  // the camera's optical axis
    const double along = forward.dot(map.frame_at(station_m).axis);
    if (std::abs(along) < 0.5) continue;  // looking at a wall, not down the tunnel
    const double ahead = (station_m - map.station_of(eye)) * (along > 0 ? 1.0 : -1.0);
    if (ahead < 0.5 || ahead > max_ahead_m) continue;
    const double cost = std::abs(ahead - preferred_ahead_m);
    if (cost < best_cost) best_cost = cost, best = StationView{static_cast<int>(i), ahead};
  }
  return best;
}

MapExtent map_extent(const StationMap& map) {
  MapExtent e{map.stations.front().station_m, map.stations.back().station_m};
  if (!map.sections.empty())
    e.from_m = std::min(e.from_m, map.sections.front().from_m), e.to_m = std::max(e.to_m, map.sections.back().to_m);
  for (const Diaphragm& d : map.girder.diaphragms)
    e.from_m = std::min(e.from_m, d.station_m), e.to_m = std::max(e.to_m, d.station_m);
  return e;
}

}  // namespace tunnelmap
