#include "core/mapping/slam_options.h"

#include "core/normals/cloud_options.h"
#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const SlamOptions& a, const SlamOptions& b) {
  return a.odometry_m_per_sqrt_m == b.odometry_m_per_sqrt_m && a.odometry_deg_per_sqrt_m == b.odometry_deg_per_sqrt_m &&
         a.odometry_in_world == b.odometry_in_world && a.band_m == b.band_m &&
         a.wall_continuity_m == b.wall_continuity_m && a.wall_turn_rad == b.wall_turn_rad && a.compartment_turn_rad == b.compartment_turn_rad && a.max_continuity_gap_m == b.max_continuity_gap_m &&
         a.max_wall_depth_m == b.max_wall_depth_m && a.max_plate_depth_m == b.max_plate_depth_m &&
         a.plate_gate_m == b.plate_gate_m && a.point_sigma_m == b.point_sigma_m &&
         a.patch_floor_m == b.patch_floor_m && a.depth_step_m == b.depth_step_m && a.correction_sigmas == b.correction_sigmas && a.gravity_rad == b.gravity_rad && a.window_groups == b.window_groups &&
         a.window_iterations == b.window_iterations &&
         a.min_odometry_m == b.min_odometry_m && a.min_odometry_deg == b.min_odometry_deg &&
         a.min_patch_points == b.min_patch_points && a.layer_tolerance_m == b.layer_tolerance_m &&
         a.max_layer_shift_m == b.max_layer_shift_m && a.max_layer_slope == b.max_layer_slope &&
         a.degenerate_ratio == b.degenerate_ratio && a.localise == b.localise &&
         a.cloud_max_range_m == b.cloud_max_range_m && a.world_up == b.world_up;
}

SlamOptions slam_options(const Parameters& p) {
  SlamOptions o;
  o.odometry_m_per_sqrt_m = mm_to_m(p.get(slam_keys::odometry_mm_per_sqrt_m));
  o.odometry_deg_per_sqrt_m = p.get(slam_keys::odometry_deg_per_sqrt_m);
  o.odometry_in_world = p.get(slam_keys::odometry_in_world);
  o.band_m = p.get(slam_keys::band_m);
  o.wall_continuity_m = mm_to_m(p.get(slam_keys::wall_continuity_mm));
  o.wall_turn_rad = p.get(slam_keys::wall_turn_deg) * M_PI / 180.0;
  o.compartment_turn_rad = p.get(slam_keys::compartment_turn_deg) * M_PI / 180.0;
  o.max_wall_depth_m = p.get(slam_keys::max_wall_depth_m);
  o.max_plate_depth_m = p.get(slam_keys::max_plate_depth_m);
  o.plate_gate_m = p.get(slam_keys::plate_gate_m);
  o.point_sigma_m = mm_to_m(p.get(slam_keys::point_sigma_mm));
  o.patch_floor_m = mm_to_m(p.get(slam_keys::patch_floor_mm));
  o.depth_step_m = mm_to_m(p.get(slam_keys::depth_step_mm));
  o.correction_sigmas = p.get(slam_keys::correction_sigmas);
  o.gravity_rad = p.get(slam_keys::gravity_deg) * M_PI / 180.0;
  o.window_groups = p.get(slam_keys::window_groups);
  o.window_iterations = p.get(slam_keys::window_iterations);
  o.localise = p.get(slam_keys::localise);
  o.cloud_max_range_m = p.get(cloud_keys::max_range_m);
  return o;
}

ParameterGroup slam_parameter_group() {
  using namespace slam_keys;
  return {{odometry_mm_per_sqrt_m.spec(), odometry_deg_per_sqrt_m.spec(), odometry_in_world.spec(), band_m.spec(),
           wall_continuity_mm.spec(), wall_turn_deg.spec(), compartment_turn_deg.spec(), max_wall_depth_m.spec(),
           max_plate_depth_m.spec(), plate_gate_m.spec(), point_sigma_mm.spec(), patch_floor_mm.spec(),
           depth_step_mm.spec(), correction_sigmas.spec(), gravity_deg.spec(), window_groups.spec(),
           window_iterations.spec(), localise.spec()},
          {}};
}

}  // namespace tunnelmap
