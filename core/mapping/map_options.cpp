#include "core/mapping/map_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const StationMapOptions& a, const StationMapOptions& b) {
  return a.station_step_m == b.station_step_m && a.design_width_m == b.design_width_m &&
         a.design_height_m == b.design_height_m && a.tolerance_mm == b.tolerance_mm &&
         a.section_change_mm == b.section_change_mm && a.min_section_stations == b.min_section_stations &&
         a.zone_gap_m == b.zone_gap_m && a.max_symmetric_step_m == b.max_symmetric_step_m &&
         a.min_support_points == b.min_support_points && a.near_range_m == b.near_range_m &&
         a.per_frame_sizes == b.per_frame_sizes && a.follow_centreline == b.follow_centreline &&
         a.centreline_window_m == b.centreline_window_m && a.centreline_node_m == b.centreline_node_m &&
         a.cloud_max_range_m == b.cloud_max_range_m && a.point_sigma_m == b.point_sigma_m;
}

StationMapOptions station_map_options(const Parameters& p) {
  StationMapOptions o;
  o.station_step_m = p.get(map_keys::station_step_m);
  o.design_width_m = design_or_none(p.get(tunnel_keys::design_width_m));
  o.design_height_m = design_or_none(p.get(tunnel_keys::design_height_m));
  o.tolerance_mm = p.get(map_keys::tolerance_mm);
  o.section_change_mm = p.get(map_keys::section_change_mm);
  o.min_section_stations = stations_in(p.get(map_keys::min_section_m), o.station_step_m);
  o.zone_gap_m = mm_to_m(p.get(tunnel_keys::zone_cluster_mm));
  o.max_symmetric_step_m = mm_to_m(p.get(tunnel_keys::symmetric_step_max_mm));
  o.min_support_points = p.get(map_keys::min_station_points);
  o.near_range_m = p.get(map_keys::near_range_m);
  o.per_frame_sizes = p.get(map_keys::per_frame_sizes);
  o.follow_centreline = p.get(map_keys::follow_centreline);
  o.centreline_window_m = p.get(map_keys::centreline_window_m);
  o.centreline_node_m = p.get(map_keys::centreline_node_m);
  o.cloud_max_range_m = p.get(cloud_keys::max_range_m);
  o.point_sigma_m = mm_to_m(p.get(slam_keys::point_sigma_mm));
  return o;
}

ParameterGroup map_parameter_group() {
  using namespace map_keys;
  return {{station_step_m.spec(), tolerance_mm.spec(), section_change_mm.spec(), min_section_m.spec(),
           min_station_points.spec(), near_range_m.spec(), per_frame_sizes.spec(),
           follow_centreline.spec(), centreline_window_m.spec(), centreline_node_m.spec()},
          {}};
}

}  // namespace tunnelmap
