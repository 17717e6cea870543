#pragma once
// The station map's parameters (map.*), declared once, and the options StationMapBuilder takes
// (which also read the tunnel's design, zone gap and symmetric step: core/tunnel/tunnel_options.h).
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/mapping/slam_options.h"
#include "core/normals/cloud_options.h"
#include "core/params/parameter_key.h"
#include "core/tunnel/tunnel_options.h"

namespace tunnelmap {

class Parameters;

namespace map_keys {
inline constexpr ParameterKey<double> station_step_m{
    "map.station_step_m", "m", 0.10, 0.02, 2.0, 0.01, Stage::Map, "Station step",
    "Distance between map stations along the tunnel axis"};
inline constexpr ParameterKey<double> tolerance_mm{
    "map.tolerance_mm", "mm", 10.0, 0.5, 500.0, 0.5, Stage::Map, "Design tolerance",
    "A station whose width or height deviates from the design by more than this is out of tolerance"};
inline constexpr ParameterKey<double> section_change_mm{
    "map.section_change_mm", "mm", 12.0, 2.0, 500.0, 0.5, Stage::Map, "Section change",
    "Stations whose width or height differs from the current section's by more than this, over at "
    "least Section length stations, start a new section; shorter runs are outliers"};
inline constexpr ParameterKey<double> min_section_m{
    "map.min_section_m", "m", 0.3, 0.05, 10.0, 0.05, Stage::Map, "Section length",
    "Shortest stretch of agreeing stations that makes a new section"};
inline constexpr ParameterKey<int> min_station_points{
    "map.min_station_points", "points", 60, 5, 100000, 5, Stage::Map, "Station support",
    "Fewest wall points (over all frames) that measure a wall at one station"};
inline constexpr ParameterKey<double> near_range_m{
    "map.near_range_m", "m", 2.5, 0.0, 20.0, 0.1, Stage::Map, "Near range",
    "A wall at a station seen within this distance of the camera by at least Station support points "
    "is measured from those views alone; farther views fill in only where no near one does (0: all views)"};
inline constexpr ParameterKey<bool> per_frame_sizes{
    "map.per_frame_sizes", "", false, 0, 1, 1, Stage::Map, "Per-frame sizes",
    "1: a station's width and height are the median of each frame's own (both walls of a pair from "
    "one pose, so drifting poses cannot split it); 0: from the walls' positions pooled over frames. "
    "Needs zone clusters that find the edge bands (the lab and field presets)"};
inline constexpr ParameterKey<bool> follow_centreline{
    "map.follow_centreline", "", true, 0, 1, 1, Stage::Map, "Follow the centre line",
    "1: stations are arc length along a smooth centre line fitted to the frames' cross-section "
    "centres, each cross-section cut perpendicular to it (a walk of a posed sequence longer than "
    "two fit windows); 0: distance along the first frame's axis"};
inline constexpr ParameterKey<double> centreline_window_m{
    "map.centreline_window_m", "m", 3.0, 0.5, 20.0, 0.1, Stage::Map, "Centre line window",
    "Half-length of the stretch of frame centres each point of the centre line is fitted to (a "
    "local quadratic): longer averages more frames, shorter follows tighter bends"};
inline constexpr ParameterKey<double> centreline_node_m{
    "map.centreline_node_m", "m", 0.25, 0.05, 2.0, 0.05, Stage::Map, "Centre line spacing",
    "Distance between the fitted centre line's points; a cross-section is cut perpendicular to the "
    "nearest one"};
}  // namespace map_keys

// Whole stations in `length_m` (at least one).
inline int stations_in(double length_m, double step_m) {
  return std::max(1, static_cast<int>(std::lround(length_m / step_m)));
}
// A design dimension of the table (0 = none).
inline std::optional<double> design_or_none(double m) {
  return m > 0 ? std::optional<double>(m) : std::nullopt;
}

struct StationMapOptions {
  double station_step_m = map_keys::station_step_m.default_value;
  // The design cross-section, if known.
  std::optional<double> design_width_m = design_or_none(tunnel_keys::design_width_m.default_value);
  std::optional<double> design_height_m = design_or_none(tunnel_keys::design_height_m.default_value);
  double tolerance_mm = map_keys::tolerance_mm.default_value;  // |deviation| above this is out of tolerance
  // Stations differing by more than this start a new section.
  double section_change_mm = map_keys::section_change_mm.default_value;
  // A shorter run is an outlier, not a section.
  int min_section_stations =
      stations_in(map_keys::min_section_m.default_value, map_keys::station_step_m.default_value);
  // Wall positions closer than this are one zone.
  double zone_gap_m = mm_to_m(tunnel_keys::zone_cluster_mm.default_value);
  double max_symmetric_step_m = mm_to_m(tunnel_keys::symmetric_step_max_mm.default_value);
  // Fewest wall points a station needs to measure a wall.
  int min_support_points = map_keys::min_station_points.default_value;
  // Views within this depth measure a station's wall where they have the support (0: all views).
  double near_range_m = map_keys::near_range_m.default_value;
  // Station sizes from each frame's own walls (drift-proof) instead of pooled positions.
  bool per_frame_sizes = map_keys::per_frame_sizes.default_value;
  // Stations along a centre line fitted to the frames (else along the first frame's axis).
  bool follow_centreline = map_keys::follow_centreline.default_value;
  double centreline_window_m = map_keys::centreline_window_m.default_value;
  double centreline_node_m = map_keys::centreline_node_m.default_value;
  // A plate's view that the cloud's range cut is too near (plates_cut_by_range): the range
  // and the depth's noise at 1 m, as localisation takes them.
  double cloud_max_range_m = cloud_keys::max_range_m.default_value;
  double point_sigma_m = mm_to_m(slam_keys::point_sigma_mm.default_value);
};
bool operator==(const StationMapOptions& a, const StationMapOptions& b);
inline bool operator!=(const StationMapOptions& a, const StationMapOptions& b) { return !(a == b); }

// The options the parameter table gives (map.*, tunnel.design_*, zone gap and symmetric step).
StationMapOptions station_map_options(const Parameters& params);
ParameterGroup map_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
