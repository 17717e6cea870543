#include "core/sim/sim_config_json.h"

#include "core/util/error.h"

namespace tunnelmap {

using nlohmann::json;

namespace {

json pose_to_json(const SimCameraPose& p) {
  return {{"y_rel", p.y_rel}, {"z_rel", p.z_rel}, {"roll_deg", p.roll_deg},
          {"pitch_deg", p.pitch_deg}, {"yaw_deg", p.yaw_deg}};
}

}  // namespace

json sim_config_to_json(const SimConfig& c) {
  json j;
  j["preset"] = c.preset;
  j["width_m"] = c.width_m;
  j["height_m"] = c.height_m;
  j["frames"] = c.frames;
  j["distance_to_manhole_m"] = c.distance_to_manhole_m ? json(*c.distance_to_manhole_m) : json();
  j["manhole_distances_m"] = c.manhole_distances_m;
  j["manhole_width_m"] = c.manhole_width_m;
  j["manhole_height_m"] = c.manhole_height_m;
  // The girder's features are written only when used (the constant tunnel keeps its bytes).
  if (c.manhole_shape != "ellipse" || c.manhole_centre_z_rel != 0.5) {
    j["manhole_shape"] = c.manhole_shape;
    j["manhole_corner_radius_m"] = c.manhole_corner_radius_m;
    j["manhole_centre_z_rel"] = c.manhole_centre_z_rel;
  }
  j["end_wall_distance_m"] = c.end_wall_distance_m ? json(*c.end_wall_distance_m) : json();
  j["seed"] = c.seed;
  j["noise_scale"] = c.noise_scale;
  j["dropout_scale"] = c.dropout_scale;
  j["roll_deg"] = c.roll_deg;
  j["pitch_deg"] = c.pitch_deg;
  j["yaw_deg"] = c.yaw_deg;
  j["edge_band_m"] = c.edge_band_m;
  j["plate_thickness_m"] = {{"left", c.plate_thickness_m[kSimLeft]},
                            {"right", c.plate_thickness_m[kSimRight]},
                            {"top", c.plate_thickness_m[kSimTop]},
                            {"bottom", c.plate_thickness_m[kSimBottom]}};
  j["rivet_radius_m"] = c.rivet_radius_m;
  j["rivet_height_m"] = c.rivet_height_m;
  j["rivet_pitch_m"] = c.rivet_pitch_m;
  j["rivet_rows_per_band"] = c.rivet_rows_per_band;
  if (!c.stiffeners.empty()) {
    json st = json::array();
    for (const SimStiffener& s : c.stiffeners)
      st.push_back({{"wall", sim_wall_name(s.wall)}, {"position_m", s.position_m}});
    j["stiffeners"] = st;
    j["stiffener_height_m"] = c.stiffener_height_m;
    j["stiffener_thickness_m"] = c.stiffener_thickness_m;
  }
  j["rust_patches_per_wall"] = c.rust_patches_per_wall;
  j["rust_roughness_m"] = c.rust_roughness_m;
  j["rust_dropout"] = c.rust_dropout;
  j["speckle_dropout"] = c.speckle_dropout;
  j["rgb_format"] = c.rgb_format;
  if (c.noise_model != "structured_light") {
    j["noise_model"] = c.noise_model;
    j["tof_sigma_m"] = c.tof_sigma_m;
    j["tof_sigma_per_m"] = c.tof_sigma_per_m;
    j["tof_flying_pixel_probability"] = c.tof_flying_pixel_probability;
    j["tof_edge_threshold_m"] = c.tof_edge_threshold_m;
  }
  j["baseline_m"] = c.baseline_m;
  j["subpixel_steps"] = c.subpixel_steps;
  j["quantize_disparity"] = c.quantize_disparity;
  j["min_depth_m"] = c.min_depth_m;
  j["max_depth_m"] = c.max_depth_m;
  j["grazing_dropout_start_deg"] = c.grazing_dropout_start_deg;
  j["grazing_dropout_full_deg"] = c.grazing_dropout_full_deg;
  json poses = json::array();
  for (const SimCameraPose& p : c.poses) poses.push_back(pose_to_json(p));
  j["poses"] = poses;
  // Written only when used, so datasets of the constant tunnel keep their exact bytes.
  if (!c.sections.empty() || c.sections_start_x_m != 0.0) {
    json sections = json::array();
    for (const SimSection& s : c.sections)
      sections.push_back(
          {{"length_m", s.length_m}, {"width_m", s.width_m}, {"height_m", s.height_m}});
    j["sections"] = sections;
    j["sections_start_x_m"] = c.sections_start_x_m;
  }
  if (!c.diaphragm_x_m.empty()) j["diaphragm_x_m"] = c.diaphragm_x_m;
  if (c.girder_length_m) j["girder_length_m"] = *c.girder_length_m;
  if (c.diaphragm_spacing_m != 0.0) j["diaphragm_spacing_m"] = c.diaphragm_spacing_m;
  if (c.curved()) {
    j["curve_radius_m"] = c.curve_radius_m;
    j["gradient_pct"] = c.gradient_pct;
    j["cross_fall_deg"] = c.cross_fall_deg;
    if (c.transition_m > 0.0) {
      j["transition_m"] = c.transition_m;
      j["transition_start_m"] = c.transition_start_m;
    }
    if (c.vertical_radius_m != 0.0) j["vertical_radius_m"] = c.vertical_radius_m;
  }
  if (c.walk) {
    j["walk"] = {{"start_x_m", c.walk->start_x_m}, {"end_x_m", c.walk->end_x_m},
                 {"stops", c.walk->stops}, {"pose", pose_to_json(c.walk->pose)}};
    if (c.walk->through_openings) j["walk"]["through_openings"] = true;
    if (c.walk->look_back) j["walk"]["look_back"] = true;
  }
  j["jitter_translation_m"] = c.jitter_translation_m;
  j["jitter_rotation_deg"] = c.jitter_rotation_deg;
  j["frame_interval_s"] = c.frame_interval_s;
  j["arm_preset"] = c.arm_preset;
  j["arm_setback_m"] = c.arm_setback_m;
  j["arm_sag_deg_per_m"] = c.arm_sag_deg_per_m;
  if (c.has_drift()) {
    j["drift_translation_mm_per_sqrt_m"] = c.drift_translation_mm_per_sqrt_m;
    j["drift_rotation_deg_per_sqrt_m"] = c.drift_rotation_deg_per_sqrt_m;
  }
  if (c.imu_gravity_deg > 0.0) j["imu_gravity_deg"] = c.imu_gravity_deg;
  return j;
}

namespace {

template <typename T>
void read(const json& j, const char* key, T& out) {
  if (j.contains(key)) out = j.at(key).get<T>();
}

template <typename T>
void read_optional(const json& j, const char* key, std::optional<T>& out) {
  if (!j.contains(key)) return;
  if (j.at(key).is_null()) out.reset();
  else out = j.at(key).get<T>();
}

SimCameraPose read_pose(const json& p) {
  SimCameraPose q;
  read(p, "y_rel", q.y_rel);
  read(p, "z_rel", q.z_rel);
  read(p, "roll_deg", q.roll_deg);
  read(p, "pitch_deg", q.pitch_deg);
  read(p, "yaw_deg", q.yaw_deg);
  return q;
}

}  // namespace

SimConfig sim_config_from_json(const json& j, const std::string& source) {
  try {
    if (!j.is_object()) throw InputError(source, "simulator settings must be a JSON object");
    SimConfig c = SimConfig::from_preset(j.value("preset", std::string("lab")));
    read(j, "width_m", c.width_m);
    read(j, "height_m", c.height_m);
    read(j, "frames", c.frames);
    read_optional(j, "distance_to_manhole_m", c.distance_to_manhole_m);
    read(j, "manhole_distances_m", c.manhole_distances_m);
    read(j, "manhole_width_m", c.manhole_width_m);
    read(j, "manhole_height_m", c.manhole_height_m);
    read(j, "manhole_shape", c.manhole_shape);
    read(j, "manhole_corner_radius_m", c.manhole_corner_radius_m);
    read(j, "manhole_centre_z_rel", c.manhole_centre_z_rel);
    read_optional(j, "end_wall_distance_m", c.end_wall_distance_m);
    read(j, "seed", c.seed);
    read(j, "noise_scale", c.noise_scale);
    read(j, "dropout_scale", c.dropout_scale);
    read(j, "roll_deg", c.roll_deg);
    read(j, "pitch_deg", c.pitch_deg);
    read(j, "yaw_deg", c.yaw_deg);
    read(j, "edge_band_m", c.edge_band_m);
    if (j.contains("plate_thickness_m")) {
      const json& t = j.at("plate_thickness_m");
      read(t, "left", c.plate_thickness_m[kSimLeft]);
      read(t, "right", c.plate_thickness_m[kSimRight]);
      read(t, "top", c.plate_thickness_m[kSimTop]);
      read(t, "bottom", c.plate_thickness_m[kSimBottom]);
    }
    read(j, "rivet_radius_m", c.rivet_radius_m);
    read(j, "rivet_height_m", c.rivet_height_m);
    read(j, "rivet_pitch_m", c.rivet_pitch_m);
    read(j, "rivet_rows_per_band", c.rivet_rows_per_band);
    if (j.contains("stiffeners")) {
      c.stiffeners.clear();
      for (const json& s : j.at("stiffeners")) {
        SimStiffener st;
        const std::string wall = s.at("wall").get<std::string>();
        st.wall = sim_wall_index(wall);
        if (st.wall < 0) throw InputError(source, "stiffener wall '" + wall + "' is not left, right, top or bottom");
        st.position_m = s.at("position_m").get<double>();
        c.stiffeners.push_back(st);
      }
    }
    read(j, "stiffener_height_m", c.stiffener_height_m);
    read(j, "stiffener_thickness_m", c.stiffener_thickness_m);
    read(j, "rust_patches_per_wall", c.rust_patches_per_wall);
    read(j, "rust_roughness_m", c.rust_roughness_m);
    read(j, "rust_dropout", c.rust_dropout);
    if (j.contains("rgb_format") && j["rgb_format"].is_string()) c.rgb_format = j["rgb_format"].get<std::string>();
    read(j, "speckle_dropout", c.speckle_dropout);
    read(j, "noise_model", c.noise_model);
    read(j, "tof_sigma_m", c.tof_sigma_m);
    read(j, "tof_sigma_per_m", c.tof_sigma_per_m);
    read(j, "tof_flying_pixel_probability", c.tof_flying_pixel_probability);
    read(j, "tof_edge_threshold_m", c.tof_edge_threshold_m);
    read(j, "baseline_m", c.baseline_m);
    read(j, "subpixel_steps", c.subpixel_steps);
    read(j, "quantize_disparity", c.quantize_disparity);
    read(j, "min_depth_m", c.min_depth_m);
    read(j, "max_depth_m", c.max_depth_m);
    read(j, "grazing_dropout_start_deg", c.grazing_dropout_start_deg);
    read(j, "grazing_dropout_full_deg", c.grazing_dropout_full_deg);
    if (j.contains("poses")) {
      c.poses.clear();
      for (const json& p : j.at("poses")) c.poses.push_back(read_pose(p));
    }
    if (j.contains("sections")) {
      c.sections.clear();
      if (!j.at("sections").is_array())
        throw InputError(source, "simulator sections must be an array");
      for (const json& s : j.at("sections")) {
        if (!s.is_object())
          throw InputError(source,
                           "every simulator section must be an object {length_m, width_m, height_m}");
        SimSection q;
        read(s, "length_m", q.length_m);
        read(s, "width_m", q.width_m);
        read(s, "height_m", q.height_m);
        c.sections.push_back(q);
      }
    }
    read(j, "sections_start_x_m", c.sections_start_x_m);
    read(j, "diaphragm_x_m", c.diaphragm_x_m);
    read_optional(j, "girder_length_m", c.girder_length_m);
    read(j, "diaphragm_spacing_m", c.diaphragm_spacing_m);
    read(j, "curve_radius_m", c.curve_radius_m);
    read(j, "gradient_pct", c.gradient_pct);
    read(j, "cross_fall_deg", c.cross_fall_deg);
    read(j, "transition_m", c.transition_m);
    read(j, "transition_start_m", c.transition_start_m);
    read(j, "vertical_radius_m", c.vertical_radius_m);
    if (j.contains("walk") && !j.at("walk").is_null()) {
      const json& w = j.at("walk");
      if (!w.is_object()) throw InputError(source, "simulator walk must be an object or null");
      SimWalk walk;
      read(w, "start_x_m", walk.start_x_m);
      read(w, "end_x_m", walk.end_x_m);
      read(w, "stops", walk.stops);
      if (w.contains("pose")) walk.pose = read_pose(w.at("pose"));
      read(w, "through_openings", walk.through_openings);
      read(w, "look_back", walk.look_back);
      c.walk = walk;
    }
    read(j, "jitter_translation_m", c.jitter_translation_m);
    read(j, "jitter_rotation_deg", c.jitter_rotation_deg);
    read(j, "frame_interval_s", c.frame_interval_s);
    read(j, "arm_preset", c.arm_preset);
    read(j, "arm_setback_m", c.arm_setback_m);
    read(j, "arm_sag_deg_per_m", c.arm_sag_deg_per_m);
    read(j, "drift_translation_mm_per_sqrt_m", c.drift_translation_mm_per_sqrt_m);
    read(j, "drift_rotation_deg_per_sqrt_m", c.drift_rotation_deg_per_sqrt_m);
    read(j, "imu_gravity_deg", c.imu_gravity_deg);
    c.validate();
    return c;
  } catch (const json::exception& e) {
    throw InputError(source, std::string("bad simulator settings: ") + e.what());
  } catch (const ParameterError& e) {
    throw InputError(source, e.what());
  }
}

}  // namespace tunnelmap
