// The typed declarations beside each module (core/*/*_options.h): the option structs' defaults
// are the table's, every declared key reaches some stage's options, and the table keeps the
// order `tunnelmap-cli params`, presets and the GUI show.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/baselines/baseline_options.h"
#include "core/baselines/method_runner.h"
#include "core/fusion/fusion_options.h"
#include "core/io/input_options.h"
#include "core/io/read_options.h"
#include "core/mapping/map_options.h"
#include "core/mapping/slam_options.h"
#include "core/normals/cloud_options.h"
#include "core/normals/normal_options.h"
#include "core/params/parameters.h"
#include "core/planes/grow_options.h"
#include "core/tunnel/tunnel_options.h"
#include "core/util/error.h"

using namespace tunnelmap;

namespace {

struct AllOptions {
  InputLimitOptions input;
  CloudOptions cloud;
  NormalOptions normals;
  GrowOptions grow;
  TunnelOptions tunnel;
  FusionOptions fusion;
  StationMapOptions map;
  SlamOptions slam;
  BaselineOptions baselines;
};

AllOptions derive(const Parameters& p) {
  return {input_limit_options(p), cloud_options(p),  normal_options(p),      grow_options(p),  tunnel_options(p),
          fusion_options(p), station_map_options(p), slam_options(p), baseline_options(p)};
}

// The stages whose options differ.
std::vector<std::string> changed(const AllOptions& a, const AllOptions& b) {
  std::vector<std::string> out;
  if (a.input != b.input) out.push_back("input");
  if (a.cloud != b.cloud) out.push_back("cloud");
  if (a.normals != b.normals) out.push_back("normals");
  if (a.grow != b.grow) out.push_back("grow");
  if (a.tunnel != b.tunnel) out.push_back("tunnel");
  if (a.fusion != b.fusion) out.push_back("fusion");
  if (a.map != b.map) out.push_back("map");
  if (a.slam != b.slam) out.push_back("slam");
  if (a.baselines != b.baselines) out.push_back("baselines");
  return out;
}

}  // namespace

TEST(ParameterDeclarations, DefaultConstructedOptionsEqualThoseOfDefaultParameters) {
  const Parameters defaults;
  EXPECT_TRUE(InputLimitOptions() == input_limit_options(defaults));
  EXPECT_TRUE(CloudOptions() == cloud_options(defaults));
  EXPECT_TRUE(NormalOptions() == normal_options(defaults));
  EXPECT_TRUE(GrowOptions() == grow_options(defaults));
  EXPECT_TRUE(TunnelOptions() == tunnel_options(defaults));
  EXPECT_TRUE(FusionOptions() == fusion_options(defaults));
  EXPECT_TRUE(SlamOptions() == slam_options(defaults));
  EXPECT_TRUE(StationMapOptions() == station_map_options(defaults));
  EXPECT_TRUE(BaselineOptions() == baseline_options(defaults));
  // The values the structs held before they took them from the declarations.
  EXPECT_EQ(InputLimitOptions().max_image_pixels, 4096LL * 4096LL);
  EXPECT_EQ(ReadOptions().max_image_pixels, 4096LL * 4096LL);
  EXPECT_EQ(GrowOptions().distance_m, 0.015);
  EXPECT_EQ(GrowOptions().candidate_distance_m, 0.040);
  EXPECT_EQ(TunnelOptions().zone_cluster_m, 0.010);
  EXPECT_EQ(TunnelOptions().context_tolerance_m, 0.040);
  EXPECT_EQ(TunnelOptions().max_symmetric_step_m, 0.03);
  EXPECT_EQ(FusionOptions().voxel_m, 0.008);
  EXPECT_EQ(FusionOptions().pose_group_m, 0.05);
  EXPECT_EQ(StationMapOptions().min_section_stations, 3);
  EXPECT_FALSE(StationMapOptions().design_width_m.has_value());
  EXPECT_EQ(RansacLseOptions().distance_m, 0.015);
  EXPECT_EQ(RansacLseOptions().iterations, 100);
  EXPECT_EQ(QhullOptions().min_points, 1000);
}

TEST(ParameterDeclarations, EveryDeclaredParameterChangesSomeStagesOptions) {
  const AllOptions base = derive(Parameters());
  for (const ParameterSpec& spec : parameter_table()) {
    // The first valid value other than the default: the range's ends, then one step away.
    Parameters p;
    bool set = false;
    for (double v : {spec.max, spec.min, spec.default_value + spec.step, spec.default_value - spec.step}) {
      if (v == spec.default_value) continue;
      try {
        p.set(spec.key, v);
        set = true;
        break;
      } catch (const ParameterError&) {
      }
    }
    ASSERT_TRUE(set) << spec.key << ": no valid value other than the default";
    EXPECT_FALSE(changed(base, derive(p)).empty()) << spec.key << " = " << p.get(spec.key)
                                                   << " is declared but no stage reads it";
  }
}

TEST(ParameterDeclarations, AKeyReachesItsOwnStageTyped) {
  Parameters p;
  p.set(grow_keys::distance_mm, 8.0);
  p.set(grow_keys::refit_normal, false);
  p.set(fusion_keys::min_weight, 5);
  EXPECT_EQ(changed(derive(Parameters()), derive(p)), (std::vector<std::string>{"grow", "fusion"}));
  EXPECT_DOUBLE_EQ(grow_options(p).distance_m, 0.008);
  EXPECT_FALSE(grow_options(p).refit_normal);
  EXPECT_EQ(p.get(fusion_keys::min_weight), 5);
  EXPECT_DOUBLE_EQ(p.get("grow.refit_normal"), 0.0);  // bool keys are 0/1 in the table
  // The design reaches the single-frame detector and the station map alike.
  p.set(tunnel_keys::design_width_m, 0.82);
  EXPECT_DOUBLE_EQ(tunnel_options(p).design_width_m, 0.82);
  ASSERT_TRUE(station_map_options(p).design_width_m.has_value());
  EXPECT_DOUBLE_EQ(*station_map_options(p).design_width_m, 0.82);
}

TEST(ParameterDeclarations, TableKeepsItsOrderAndAddsTheBaselinesLast) {
  const std::vector<std::string> expected = {
      "input.max_image_pixels", "cloud.max_range_m", "cloud.min_range_m", "normals.smoothing_px", "normals.max_depth_change",
      "grow.angle_deg", "grow.distance_mm", "grow.candidate_distance_mm", "grow.neighbourhood_n",
      "grow.min_points", "grow.min_area_m2", "grow.refit_normal", "grow.grid_step", "grow.edge_on_pass", "grow.cell_px",
      "tunnel.class_angle_deg", "tunnel.outlier_bin_deg", "tunnel.outlier_max_deg", "tunnel.zone_cluster_mm",
      "tunnel.min_cluster_points", "tunnel.zone_support_ref_m", "tunnel.zone_gap_ref_m",
      "tunnel.context_tolerance_mm", "tunnel.max_pair_angle_deg", "tunnel.symmetric_step_max_mm",
      "tunnel.width_min_m", "tunnel.width_max_m", "tunnel.height_min_m", "tunnel.height_max_m",
      "zones.forbidden_band_m", "tunnel.design_width_m", "tunnel.design_height_m", "map.station_step_m",
      "map.tolerance_mm", "map.section_change_mm", "map.min_section_m", "map.min_station_points", "map.near_range_m", "map.per_frame_sizes",
      "map.follow_centreline", "map.centreline_window_m", "map.centreline_node_m",
      "slam.odometry_mm_per_sqrt_m", "slam.odometry_deg_per_sqrt_m", "slam.odometry_in_world", "slam.band_m", "slam.wall_continuity_mm", "slam.wall_turn_deg", "slam.compartment_turn_deg",
      "slam.max_wall_depth_m", "slam.max_plate_depth_m", "slam.plate_gate_m", "slam.point_sigma_mm",
      "slam.patch_floor_mm", "slam.depth_step_mm", "slam.correction_sigmas", "slam.gravity_deg", "slam.window_groups", "slam.window_iterations", "slam.localise",
      "fusion.voxel_mm", "fusion.truncation_mm", "fusion.max_depth_m", "fusion.max_weight", "fusion.min_weight",
      "fusion.bounds_margin_m", "fusion.max_extent_m", "fusion.max_volume_mb", "fusion.pose_group_mm", "fusion.offset_fit_frames",
      "ransac.iterations",
      "ransac.sample_step", "ransac.distance_mm", "ransac.max_planes", "ransac.min_plane_points",
      "ransac.max_trials", "ransac.confidence", "qhull.sample_step", "qhull.min_points",
      "qhull.yaw_range_deg", "qhull.tilt_range_deg"};
  std::vector<std::string> keys;
  for (const ParameterSpec& s : parameter_table()) keys.push_back(s.key);
  EXPECT_EQ(keys, expected);
  for (const ParameterSpec& s : parameter_table())
    EXPECT_EQ(std::string(stage_name(s.stage)) == "baselines",
              s.key.rfind("ransac.", 0) == 0 || s.key.rfind("qhull.", 0) == 0)
        << s.key;
}

TEST(ParameterDeclarations, TheBaselinesRunWithTheirTableKeys) {
  Parameters p;
  p.set(baseline_keys::ransac_iterations, 7);
  p.set(baseline_keys::qhull_sample_step, 4);
  MethodRunner from_params(Method::Ransac, p);
  EXPECT_EQ(from_params.baselines().ransac.iterations, 7);
  EXPECT_EQ(from_params.baselines().qhull.sample_step, 4);
  // Explicit options (the evaluation protocol's) still win.
  MethodRunner explicit_options(Method::Ransac, p, BaselineOptions());
  EXPECT_EQ(explicit_options.baselines().ransac.iterations, 100);
}
