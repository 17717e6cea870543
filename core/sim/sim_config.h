#pragma once
// SimConfig: every knob of the simulated tunnel depth camera (core/sim). from_preset() fills
// the values for the paper's two experiments; validate() range-checks them. Geometry, sensor
// model and presets are described in docs/simulator.md.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tunnelmap {

// A nominal camera pose inside the tunnel cross-section. The position is relative to the
// cross-section so that presets stay valid when width/height are overridden:
// y = y_rel * W (left positive), z = z_rel * H (floor = 0). Angles turn the neutral
// "looking along +X" orientation: yaw about world Z (left positive), pitch nose-up positive,
// roll about the viewing axis (clockwise as seen by the camera positive).
struct SimCameraPose {
  double y_rel = 0.0;
  double z_rel = 0.5;
  double roll_deg = 0.0;
  double pitch_deg = 0.0;
  double yaw_deg = 0.0;
};

// One stretch of constant cross-section (see SimConfig::sections).
struct SimSection {
  double length_m = 1.0;
  double width_m = 0.82;
  double height_m = 1.30;
};

// A walk of the robot along the tunnel: `stops` camera stations evenly spaced from start_x_m
// to end_x_m (world X), one contiguous pose group per stop, each at `pose` (relative to the
// cross-section of the section at that station).
// With `through_openings`, the camera follows the manholes near every plate: within 0.5 m of a
// plate's station it is at the opening's centre (y = 0, z = the opening's centre height),
// from 1.5 m on at `pose`, blended smoothly in between (docs/simulator.md#long-girders).
// With `look_back`, the stop nearest the middle of each compartment after a plate (between two
// plates, or the last plate and the walk's end) turns the camera round to look back along the
// girder: the stretch just past a plate is hidden by the plate from the frames before it and
// lies below the field of view of those just past it, and only a look back sees it.
struct SimWalk {
  double start_x_m = 0.0, end_x_m = 2.0;
  int stops = 5;
  SimCameraPose pose;
  bool through_openings = false;
  bool look_back = false;
};

// A longitudinal stiffener: a flat bar along a wall (docs/simulator.md#longitudinal-stiffeners)
// centred at `position_m` across it: the height above the floor on the left and right walls,
// y (left positive) on the roof and the floor.
struct SimStiffener {
  int wall = 0;  // SimWall
  double position_m = 0.5;
};

// Wall order used for per-wall arrays: left (y = +W/2), right (y = -W/2), top (z = H),
// bottom (z = 0).
enum SimWall { kSimLeft = 0, kSimRight = 1, kSimTop = 2, kSimBottom = 3 };
// kSimLeft -> "left", ... and back (-1 for other names).
inline const char* sim_wall_name(int wall) {
  static const char* const kNames[4] = {"left", "right", "top", "bottom"};
  return wall >= 0 && wall < 4 ? kNames[wall] : "?";
}
inline int sim_wall_index(const std::string& name) {
  return name == "left" ? kSimLeft : name == "right" ? kSimRight : name == "top" ? kSimTop
       : name == "bottom" ? kSimBottom : -1;
}

// Default-constructed = the lab preset.
struct SimConfig {
  std::string preset = "lab";  // "lab" | "field"
  double width_m = 0.82;       // W: between the outermost (edge-band) surfaces
  double height_m = 1.30;      // H
  // Sections whose cross-section changes along the tunnel. Empty = one constant section of
  // width_m x height_m; otherwise width_m/height_m are not used by the geometry. Section k
  // spans [x_k, x_k + length_k) with x_0 = sections_start_x_m; the first section continues
  // before x_0 and the last one after its end. Cross-sections stay centred on y = 0, floor z = 0.
  std::vector<SimSection> sections;
  double sections_start_x_m = 0.0;
  int frames = 30;             // total frames, split into contiguous pose groups

  // Manhole plate. `distance_to_manhole_m` forces one distance for every frame; otherwise the
  // groups cycle through `manhole_distances_m` (empty = no manhole plate).
  std::optional<double> distance_to_manhole_m;
  std::vector<double> manhole_distances_m;
  double manhole_width_m = 0.45;   // the opening of every plate, centred across the section
  double manhole_height_m = 0.70;
  std::string manhole_shape = "ellipse";  // "ellipse" | "rounded_rectangle"
  double manhole_corner_radius_m = 0.10;  // rounded_rectangle: radius of its four corners
  double manhole_centre_z_rel = 0.5;      // centre height of the opening / H of its section
  // Manhole diaphragms: more transverse plates at these world X positions, each with the same
  // opening, centred in that section's cross-section. Seen from both sides.
  std::vector<double> diaphragm_x_m;
  // A whole girder (docs/simulator.md#long-girders): stations 0..girder_length_m, a start wall
  // at 0 and the end wall at girder_length_m (end_wall_distance_m is then not used), and with
  // diaphragm_spacing_m > 0 diaphragms at S, 2S, ... at least S/2 short of the end (besides
  // diaphragm_x_m).
  std::optional<double> girder_length_m;
  double diaphragm_spacing_m = 0.0;
  // Alignment (docs/simulator.md#curves): horizontal curve radius (0 = straight; > 0 turns
  // left, < 0 right), constant gradient in percent (> 0 rises with the station) and cross-fall
  // (roll of the cross-section about the girder axis; > 0 lifts the left wall). Any of them
  // makes the girder a chain of straight compartments (core/sim/sim_alignment.h).
  double curve_radius_m = 0.0;
  double gradient_pct = 0.0;
  double cross_fall_deg = 0.0;
  // A transition curve (clothoid) into the horizontal curve: the girder runs straight up to
  // station transition_start_m, then its curvature grows evenly over transition_m metres to
  // 1 / curve_radius_m. 0: the curve runs the whole girder.
  double transition_m = 0.0;
  double transition_start_m = 0.0;
  // Vertical curve (a crest < 0, a sag > 0): the gradient changes by 1 / vertical_radius_m per
  // metre, gradient_pct being the one at station 0. 0: the gradient is constant.
  double vertical_radius_m = 0.0;
  bool curved() const {
    return curve_radius_m != 0.0 || gradient_pct != 0.0 || cross_fall_deg != 0.0 || vertical_radius_m != 0.0;
  }
  // End wall: this far beyond the manhole plate if there is one, else beyond the camera (with
  // a walk: beyond its furthest station, or the plate if that is further).
  std::optional<double> end_wall_distance_m = 3.0;

  unsigned seed = 1;
  double noise_scale = 1.0;    // multiplies axial/lateral noise and rust roughness
  double dropout_scale = 1.0;  // multiplies every dropout probability
  double roll_deg = 0.0, pitch_deg = 0.0, yaw_deg = 0.0;  // added to every pose

  // Walls: each is edge band | middle plate | edge band across its width.
  double edge_band_m = 0.15;                                    // forbidden-zone width
  std::array<double, 4> plate_thickness_m{0.008, 0.008, 0.008, 0.008};  // left,right,top,bottom
  // Rivets: spherical-cap domes in rows along X on every edge band (rows staggered).
  double rivet_radius_m = 0.009;  // base radius of the dome
  double rivet_height_m = 0.006;
  double rivet_pitch_m = 0.070;
  int rivet_rows_per_band = 2;
  // Longitudinal stiffeners: flat bars standing stiffener_height_m out of the wall's surface
  // (edge band or middle plate), stiffener_thickness_m thick, along every section.
  std::vector<SimStiffener> stiffeners;
  double stiffener_height_m = 0.10;
  double stiffener_thickness_m = 0.010;
  // Rust: elliptic patches per wall with roughness and extra dropout.
  int rust_patches_per_wall = 2;
  double rust_roughness_m = 0.001;  // amplitude of the surface relief on rust
  double rust_dropout = 0.25;       // extra dropout probability on rust
  double speckle_dropout = 0.01;    // random isolated dropouts everywhere
  std::string rgb_format = "png";   // colour image files: "png" (lossless) or "jpg" (small)

  // Depth noise model (docs/simulator.md#sensor-model): "structured_light" (PrimeSense /
  // Structure Sensor class: lateral jitter, axial sigma growing as z^2, disparity quantisation)
  // or "tof" (time of flight: sigma = (tof_sigma_m + tof_sigma_per_m * z) / sqrt(cos theta), no
  // quantisation, no lateral jitter, flying pixels mixing the depths across depth edges).
  std::string noise_model = "structured_light";
  double tof_sigma_m = 0.0015;                 // at zero depth, normal incidence
  double tof_sigma_per_m = 0.0015;             // growth per metre of depth
  double tof_flying_pixel_probability = 0.5;   // of a pixel at a depth edge
  double tof_edge_threshold_m = 0.05;          // depth jump to a 4-neighbour that makes an edge

  // Sensor (structured light, PrimeSense / Structure Sensor class).
  double baseline_m = 0.075;
  int subpixel_steps = 8;           // disparity quantised to 1/subpixel_steps pixel
  bool quantize_disparity = true;
  double min_depth_m = 0.4;
  double max_depth_m = 6.0;
  double grazing_dropout_start_deg = 70.0;  // dropout probability 0 here ...
  double grazing_dropout_full_deg = 85.0;   // ... rising to 1 here

  // Camera poses and per-frame jitter (so frames of one pose differ).
  // Default = lab preset: hanging from the roof, near the left wall, low right rolled/yawed.
  std::vector<SimCameraPose> poses{{0.0, 0.85, 0.0, -15.0, 0.0},
                                   {0.27, 0.50, 0.0, -3.0, -10.0},
                                   {-0.18, 0.35, 10.0, 5.0, 8.0}};
  // When set, replaces the pose groups above (and the manhole distances' camera placement).
  std::optional<SimWalk> walk;
  double jitter_translation_m = 0.002;
  double jitter_rotation_deg = 0.2;
  double frame_interval_s = 1.0 / 30.0;

  // Eye-in-hand arm (docs/kinematics.md). Empty = no arm: frames carry their exact "pose".
  // Otherwise each frame's wanted pose is reached by inverse kinematics of this robot preset
  // (base on the floor centre, `arm_setback_m` behind the camera's pose group), the dataset
  // gets "robot" and per-frame "joints", and the camera is rendered at the sagged pose
  // (written as "pose_true", not "pose", so readers use forward kinematics).
  std::string arm_preset;
  double arm_setback_m = 0.45;
  double arm_sag_deg_per_m = 0.0;  // link sag: droop angle per metre of horizontal reach

  // Odometry drift (docs/simulator.md#odometry-drift): a seeded random walk along the distance
  // the camera travelled from pose group to pose group. Each of the three translation
  // components gains N(0, (drift_translation_mm_per_sqrt_m / 1000)^2 * ds) and the rotation
  // error turns by N(0, (drift_rotation_deg_per_sqrt_m)^2 * ds) degrees about each world axis
  // for ds metres travelled. Frames of one pose group share their group's drift. The dataset's
  // "pose" (or, with an arm, its "robot_base") carries the drift; "pose_true" the truth.
  double drift_translation_mm_per_sqrt_m = 0.0;
  double drift_rotation_deg_per_sqrt_m = 0.0;
  bool has_drift() const {
    return drift_translation_mm_per_sqrt_m > 0.0 || drift_rotation_deg_per_sqrt_m > 0.0;
  }
  // An IMU on the camera: with a value above 0, every frame carries "gravity", where things
  // fall in the true camera frame, tilted by N(0, imu_gravity_deg^2) about each of its two
  // axes across it (seeded per frame). An accelerometer at rest is that good; the drift of the
  // poses does not reach it.
  double imu_gravity_deg = 0.0;

  // Throws ParameterError (one line) for unknown names.
  static SimConfig from_preset(const std::string& name);
  // Throws ParameterError (one line) for the first out-of-range value.
  void validate() const;
};

}  // namespace tunnelmap
