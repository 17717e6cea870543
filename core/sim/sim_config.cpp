#include "core/sim/sim_config.h"

#include <cmath>
#include <sstream>

#include "core/sim/sim_girder.h"
#include "core/sim/sim_sections.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_range(const char* name, double v, double lo, double hi) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw ParameterError("simulator: " + std::string(name) + " = " + fmt(v) +
                         " is out of range [" + fmt(lo) + ", " + fmt(hi) + "]");
}

void check_pose(const char* what, const SimCameraPose& p, double max_t, double width,
                double height) {
  // Keep the camera at least 2 cm inside the middle plates.
  const std::string w(what);
  check_range((w + " y_rel").c_str(), p.y_rel, -0.5 + (max_t + 0.02) / width,
              0.5 - (max_t + 0.02) / width);
  check_range((w + " z_rel").c_str(), p.z_rel, (max_t + 0.02) / height,
              1.0 - (max_t + 0.02) / height);
  check_range((w + " roll_deg").c_str(), p.roll_deg, -60.0, 60.0);
  check_range((w + " pitch_deg").c_str(), p.pitch_deg, -60.0, 60.0);
  check_range((w + " yaw_deg").c_str(), p.yaw_deg, -60.0, 60.0);
}

// Sections, diaphragms and the walk (docs/simulator.md); positions within +-1 km.
void check_layout(const SimConfig& c) {
  constexpr double kFar = 1000.0;
  if (c.sections.size() > 1000)
    throw ParameterError("simulator: " + std::to_string(c.sections.size()) +
                         " sections is too many (at most 1000)");
  for (std::size_t k = 0; k < c.sections.size(); ++k) {
    const SimSection& s = c.sections[k];
    const std::string name = "sections[" + std::to_string(k) + "]";
    if (!std::isfinite(s.length_m) || s.length_m <= 0.0 || s.length_m > kFar)
      throw ParameterError("simulator: " + name + ".length_m = " + fmt(s.length_m) +
                           " must be > 0 and at most " + fmt(kFar));
    check_range((name + ".width_m").c_str(), s.width_m, 0.3, 5.0);
    check_range((name + ".height_m").c_str(), s.height_m, 0.3, 5.0);
  }
  check_range("sections_start_x_m", c.sections_start_x_m, -kFar, kFar);
  if (c.diaphragm_x_m.size() > 1000)
    throw ParameterError("simulator: " + std::to_string(c.diaphragm_x_m.size()) +
                         " diaphragms is too many (at most 1000)");
  for (double x : c.diaphragm_x_m) check_range("diaphragm_x_m", x, -kFar, kFar);
  if (c.girder_length_m) check_range("girder_length_m", *c.girder_length_m, 1.0, kFar);
  if (c.diaphragm_spacing_m != 0.0) {
    if (!c.girder_length_m)
      throw ParameterError("simulator: diaphragm_spacing_m needs girder_length_m (the girder's length)");
    check_range("diaphragm_spacing_m", c.diaphragm_spacing_m, 0.5, 100.0);
  }
  const std::size_t plates = sim::diaphragm_stations(c).size();
  if (plates > 1000)
    throw ParameterError("simulator: " + std::to_string(plates) +
                         " diaphragms is too many (at most 1000)");
  if (c.walk) {
    check_range("walk start_x_m", c.walk->start_x_m, -kFar, kFar);
    check_range("walk end_x_m", c.walk->end_x_m, -kFar, kFar);
    check_range("walk stops", c.walk->stops, 1, 100000);
    if (c.frames < c.walk->stops)
      throw ParameterError("simulator: frames = " + std::to_string(c.frames) +
                           " is fewer than the walk's " + std::to_string(c.walk->stops) +
                           " stops (each stop needs a frame)");
    if (c.walk->look_back && c.walk->end_x_m < c.walk->start_x_m)
      throw ParameterError("simulator: a walk that looks back must run forward (end_x_m below start_x_m)");
    if (c.walk->look_back && plates == 0 && !sim::manhole_plate_x(c))
      throw ParameterError("simulator: a walk that looks back needs plates to look back at (no diaphragms)");
  }
}

}  // namespace

SimConfig SimConfig::from_preset(const std::string& name) {
  SimConfig c;
  if (name == "lab") {
    // Experiment 1: lab rig 0.82 x 1.30 m, robot on the roof or a wall, 3 poses x 10 frames.
    c.preset = "lab";
    c.width_m = 0.82;
    c.height_m = 1.30;
    c.frames = 30;
    c.end_wall_distance_m = 3.0;
    c.plate_thickness_m = {0.008, 0.008, 0.008, 0.008};
    c.rust_patches_per_wall = 2;
    c.rust_roughness_m = 0.001;
    c.rust_dropout = 0.25;
    c.speckle_dropout = 0.01;
    c.poses = {
        {0.0, 0.75, 0.0, -6.0, 0.0},     // hanging from the roof, pitched down
        {0.27, 0.50, 0.0, -3.0, -10.0},  // near the left wall, turned away from it
        {-0.18, 0.35, 10.0, 5.0, 8.0},   // low on the right, rolled and yawed
    };
    c.jitter_translation_m = 0.002;
    c.jitter_rotation_deg = 0.2;
    return c;
  }
  if (name == "field") {
    // Experiment 2: steel bridge 0.84 x 1.20 m, frames at 5, 3 and 1.8 m from the manhole,
    // rusty surfaces, plates of different thickness per wall, rougher data.
    c.preset = "field";
    c.width_m = 0.84;
    c.height_m = 1.20;
    c.frames = 30;
    c.manhole_distances_m = {5.0, 3.0, 1.8};
    c.end_wall_distance_m.reset();
    c.noise_scale = 1.3;
    c.plate_thickness_m = {0.010, 0.006, 0.012, 0.008};
    c.rust_patches_per_wall = 6;
    c.rust_roughness_m = 0.003;
    c.rust_dropout = 0.40;
    c.speckle_dropout = 0.02;
    c.poses = {
        {0.15, 0.55, 3.0, -5.0, -8.0},
        {-0.10, 0.75, 0.0, -10.0, 0.0},
        {0.0, 0.40, -4.0, 5.0, 5.0},
    };
    c.jitter_translation_m = 0.003;
    c.jitter_rotation_deg = 0.3;
    return c;
  }
  throw ParameterError("simulator: unknown preset '" + name + "' (expected lab or field)");
}

void SimConfig::validate() const {
  if (preset != "lab" && preset != "field")
    throw ParameterError("simulator: unknown preset '" + preset + "' (expected lab or field)");
  check_range("width_m", width_m, 0.3, 5.0);
  check_range("height_m", height_m, 0.3, 5.0);
  check_range("frames", frames, 1, 100000);
  check_layout(*this);
  // Checks that depend on the cross-section hold for the smallest section.
  const sim::SimSections layout(*this);
  const double min_w = layout.min_width(), min_h = layout.min_height();
  if (distance_to_manhole_m) check_range("distance_to_manhole_m", *distance_to_manhole_m, 0.5, 50.0);
  for (double d : manhole_distances_m) check_range("manhole_distances_m", d, 0.5, 50.0);
  if (manhole_shape != "ellipse" && manhole_shape != "rounded_rectangle")
    throw ParameterError("simulator: manhole_shape must be ellipse or rounded_rectangle, got '" +
                         manhole_shape + "'");
  if (distance_to_manhole_m || !manhole_distances_m.empty() || !sim::diaphragm_stations(*this).empty()) {
    check_range("manhole_width_m", manhole_width_m, 0.05, min_w - 0.02);
    check_range("manhole_height_m", manhole_height_m, 0.05, min_h - 0.02);
    // 1 cm to spare above and below in the lowest section.
    const double margin = (0.5 * manhole_height_m + 0.01) / min_h;
    check_range("manhole_centre_z_rel", manhole_centre_z_rel, margin, 1.0 - margin);
    if (manhole_shape == "rounded_rectangle")
      check_range("manhole_corner_radius_m", manhole_corner_radius_m, 0.0,
                  0.5 * std::min(manhole_width_m, manhole_height_m));
  }
  if (end_wall_distance_m) check_range("end_wall_distance_m", *end_wall_distance_m, 0.1, 100.0);
  check_range("noise_scale", noise_scale, 0.0, 10.0);
  check_range("dropout_scale", dropout_scale, 0.0, 100.0);
  check_range("roll_deg", roll_deg, -60.0, 60.0);
  check_range("pitch_deg", pitch_deg, -60.0, 60.0);
  check_range("yaw_deg", yaw_deg, -60.0, 60.0);
  const double min_side = std::min(min_w, min_h);
  check_range("edge_band_m", edge_band_m, 0.0, 0.5 * min_side - 0.05);
  for (double t : plate_thickness_m) check_range("plate_thickness_m", t, 0.0, 0.05);
  check_range("rivet_radius_m", rivet_radius_m, 0.001, 0.05);
  check_range("rivet_height_m", rivet_height_m, 0.0, rivet_radius_m);
  check_range("rivet_pitch_m", rivet_pitch_m, 2.0 * rivet_radius_m, 1.0);
  check_range("rivet_rows_per_band", rivet_rows_per_band, 0, 10);
  if (stiffeners.size() > 40)
    throw ParameterError("simulator: " + std::to_string(stiffeners.size()) +
                         " stiffeners is too many (at most 40)");
  if (!stiffeners.empty()) {
    check_range("stiffener_height_m", stiffener_height_m, 0.01, 0.3 * min_side);
    check_range("stiffener_thickness_m", stiffener_thickness_m, 0.002, 0.05);
  }
  for (const SimStiffener& st : stiffeners) {
    if (st.wall < 0 || st.wall > 3)
      throw ParameterError("simulator: stiffener wall " + std::to_string(st.wall) +
                           " is not 0-3 (left, right, top, bottom)");
    // Across the wall, clear of its corners in the smallest section.
    const double half = st.wall < 2 ? 0.5 * min_h : 0.5 * min_w;
    const double lo = st.wall < 2 ? 0.0 : -half, hi = st.wall < 2 ? 2.0 * half : half;
    check_range("stiffener position_m", st.position_m, lo + stiffener_thickness_m,
                hi - stiffener_thickness_m);
  }
  check_range("rust_patches_per_wall", rust_patches_per_wall, 0, 100);
  check_range("rust_roughness_m", rust_roughness_m, 0.0, 0.02);
  check_range("rust_dropout", rust_dropout, 0.0, 1.0);
  check_range("speckle_dropout", speckle_dropout, 0.0, 1.0);
  if (rgb_format != "png" && rgb_format != "jpg")
    throw ParameterError("simulator: rgb_format must be png or jpg, got '" + rgb_format + "'");
  if (noise_model != "structured_light" && noise_model != "tof")
    throw ParameterError("simulator: noise_model must be structured_light or tof, got '" +
                         noise_model + "'");
  check_range("tof_sigma_m", tof_sigma_m, 0.0, 0.1);
  check_range("tof_sigma_per_m", tof_sigma_per_m, 0.0, 0.1);
  check_range("tof_flying_pixel_probability", tof_flying_pixel_probability, 0.0, 1.0);
  check_range("tof_edge_threshold_m", tof_edge_threshold_m, 0.001, 10.0);
  check_range("baseline_m", baseline_m, 0.01, 1.0);
  check_range("subpixel_steps", subpixel_steps, 1, 64);
  check_range("max_depth_m", max_depth_m, 0.5, 65.0);  // 16-bit millimetres
  check_range("min_depth_m", min_depth_m, 0.0, max_depth_m - 0.1);
  check_range("grazing_dropout_full_deg", grazing_dropout_full_deg, 1.0, 90.0);
  check_range("grazing_dropout_start_deg", grazing_dropout_start_deg, 0.0,
              grazing_dropout_full_deg - 0.1);
  const double max_t = std::max(std::max(plate_thickness_m[0], plate_thickness_m[1]),
                                std::max(plate_thickness_m[2], plate_thickness_m[3]));
  if (walk) {
    check_pose("walk pose", walk->pose, max_t, min_w, min_h);  // the walk replaces `poses`
  } else {
    if (poses.empty()) throw ParameterError("simulator: no camera poses configured");
    for (const SimCameraPose& p : poses) check_pose("pose", p, max_t, min_w, min_h);
  }
  check_range("jitter_translation_m", jitter_translation_m, 0.0, 0.05);
  check_range("jitter_rotation_deg", jitter_rotation_deg, 0.0, 5.0);
  check_range("frame_interval_s", frame_interval_s, 1e-6, 3600.0);
  if (!arm_preset.empty() && arm_preset != "inchworm7")
    throw ParameterError("simulator: arm_preset must be empty or inchworm7, got '" + arm_preset + "'");
  check_range("arm_setback_m", arm_setback_m, 0.0, 1.0);
  check_range("arm_sag_deg_per_m", arm_sag_deg_per_m, 0.0, 10.0);
  check_range("drift_translation_mm_per_sqrt_m", drift_translation_mm_per_sqrt_m, 0.0, 100.0);
  check_range("drift_rotation_deg_per_sqrt_m", drift_rotation_deg_per_sqrt_m, 0.0, 5.0);
  check_range("imu_gravity_deg", imu_gravity_deg, 0.0, 10.0);
  if (curve_radius_m != 0.0) {
    if (!std::isfinite(curve_radius_m) || std::abs(curve_radius_m) < 50.0 ||
        std::abs(curve_radius_m) > 1e6)
      throw ParameterError("simulator: curve_radius_m = " + fmt(curve_radius_m) +
                           " must be 0 (straight) or between 50 and 1e+06 in size");
  }
  check_range("gradient_pct", gradient_pct, -10.0, 10.0);
  check_range("cross_fall_deg", cross_fall_deg, -10.0, 10.0);
  check_range("transition_m", transition_m, 0.0, 1000.0);
  check_range("transition_start_m", transition_start_m, -1000.0, 10000.0);
  if (transition_m > 0.0 && curve_radius_m == 0.0)
    throw ParameterError("simulator: transition_m needs a curve (curve_radius_m not 0)");
  if (vertical_radius_m != 0.0) {
    if (!std::isfinite(vertical_radius_m) || std::abs(vertical_radius_m) < 200.0 ||
        std::abs(vertical_radius_m) > 1e6)
      throw ParameterError("simulator: vertical_radius_m = " + fmt(vertical_radius_m) +
                           " must be 0 (constant gradient) or between 200 and 1e+06 in size");
  }
  if (curved() && !arm_preset.empty())
    throw ParameterError("simulator: arm_preset needs a straight girder (curve_radius_m, "
                         "gradient_pct, cross_fall_deg and vertical_radius_m 0)");
}

}  // namespace tunnelmap
