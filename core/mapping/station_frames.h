#pragma once
// Which frame shows a station best: for a station picked on the tunnel's profile, the frame
// whose camera looks at it from about 1.5 m (near enough to measure it densely, far enough to
// see all four walls), and the station's distance ahead of that camera, so the per-frame views
// (3D, cross-section) can show it.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

struct StationView {
  int frame = 0;          // index into the sequence
  double ahead_m = 0.0;   // the station's distance ahead of that frame's camera along the axis
};

// Where the map runs: from its first section's start to its last section's end (half a station
// beyond the first and last), widened to any plate beyond them (such as an end wall seen ahead).
// `map` must have stations.
struct MapExtent {
  double from_m = 0.0, to_m = 0.0;
  bool contains(double station_m) const { return station_m >= from_m && station_m <= to_m; }
};
MapExtent map_extent(const StationMap& map);

// `poses[i]`: camera-to-world of frame i (refined when the map was built with refined poses);
// `detected[i]`: frame i found the tunnel (others are never chosen). Frames that see the station
// between 0.5 m and `max_ahead_m` ahead are candidates; the one nearest `preferred_ahead_m` wins.
// None when no frame sees it.
std::optional<StationView> frame_for_station(const StationMap& map, const std::vector<Eigen::Isometry3d>& poses,
                                             const std::vector<bool>& detected, double station_m,
                                             double preferred_ahead_m = 1.5, double max_ahead_m = 4.5);

}  // namespace tunnelmap
