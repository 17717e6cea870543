// `tunnelmap-cli simulate OUT_DIR`: writes a simulated tunnel dataset (core/sim).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/cli/commands.h"
#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/sim/sim_spec_parse.h"
#include "core/sim/sim_tum_writer.h"
#include "core/util/error.h"

namespace tunnelmap::cli {

namespace {

struct SimulateOptions {
  std::string out_dir;
  std::string preset = "lab";
  std::optional<double> width, height, distance, noise_scale, dropout_scale;
  std::optional<double> roll, pitch, yaw;
  std::optional<int> frames;
  std::optional<long long> seed;
  std::string rgb_format = "png";
  std::string noise_model;  // empty = the preset's (structured_light)
  std::string format = "dataset";  // output layout: dataset (dataset.json) or tum (TUM RGB-D)
  std::string arm;                 // robot preset: joints instead of poses
  std::optional<double> sag;       // arm link sag, deg per metre of reach
  std::optional<std::string> sections, diaphragms, walk, walk_pose;  // lists, parsed in run()
  std::optional<double> sections_start;
  std::optional<std::string> drift;  // MM,DEG per sqrt(m)
  std::optional<double> imu;         // gravity per frame, deg (1 sigma)
  std::optional<double> girder, diaphragm_spacing, curve_radius, gradient_pct, cross_fall_deg;
  std::optional<std::string> transition;  // START,LENGTH
  std::optional<double> vertical_radius;
  std::optional<std::string> manhole;  // SHAPE,W,H,CENTRE_Z_REL[,CORNER_R]
  std::optional<std::string> stiffeners, stiffener_size;  // WALL:POS,...; H,T
  bool look_back = false;  // the walk turns round once per compartment
  bool quiet = false;
};

// One-line ParameterError naming the option, so the user sees which flag to fix.
void check(const char* flag, const std::optional<double>& v, double lo, double hi) {
  if (v && !(*v >= lo && *v <= hi)) {
    std::ostringstream s;
    s << "simulate: " << flag << " " << *v << " is out of range [" << lo << ", " << hi << "]";
    throw ParameterError(s.str());
  }
}

// The same for one value inside a list flag (--sections, --walk, ...).
void check(const char* flag, const char* what, double v, double lo, double hi) {
  if (!(v >= lo && v <= hi)) {
    std::ostringstream s;
    s << "simulate: " << flag << ": " << what << " " << v << " is out of range [" << lo << ", "
      << hi << "]";
    throw ParameterError(s.str());
  }
}

[[noreturn]] void refuse(const std::string& problem) {
  throw ParameterError("simulate: " + problem);
}

// --sections, --sections-start, --diaphragms, --walk, --walk-pose.
void apply_layout(const SimulateOptions& o, SimConfig& c) {
  if (o.sections) {
    if (o.width || o.height)
      refuse("--width/--height do not apply with --sections (each section has its own size)");
    c.sections = parse_sim_sections("--sections", *o.sections);
    for (std::size_t k = 0; k < c.sections.size(); ++k) {
      const std::string n = "section " + std::to_string(k + 1);
      check("--sections", (n + " width").c_str(), c.sections[k].width_m, 0.3, 5.0);
      check("--sections", (n + " height").c_str(), c.sections[k].height_m, 0.3, 5.0);
      check("--sections", (n + " length").c_str(), c.sections[k].length_m, 1e-9, 1000.0);
    }
  }
  if (o.sections_start) {
    if (!o.sections) refuse("--sections-start needs --sections");
    check("--sections-start", o.sections_start, -1000.0, 1000.0);
    c.sections_start_x_m = *o.sections_start;
  }
  if (o.diaphragms) {
    c.diaphragm_x_m = parse_sim_numbers("--diaphragms", *o.diaphragms);
    for (double x : c.diaphragm_x_m) check("--diaphragms", "position", x, -1000.0, 1000.0);
  }
  if (o.girder) {
    check("--girder", o.girder, 1.0, 1000.0);
    if (o.distance) refuse("--distance-to-manhole does not apply with --girder (its plates are the diaphragms)");
    c.girder_length_m = *o.girder;
    c.manhole_distances_m.clear();  // the field preset's plate: a girder has its diaphragms
    c.distance_to_manhole_m.reset();
  }
  if (o.diaphragm_spacing) {
    if (!o.girder) refuse("--diaphragm-spacing needs --girder");
    check("--diaphragm-spacing", o.diaphragm_spacing, 0.5, 100.0);
    c.diaphragm_spacing_m = *o.diaphragm_spacing;
  }
  if (o.manhole) {
    const std::string& text = *o.manhole;
    const auto comma = text.find(',');
    const std::string shape = text.substr(0, comma);
    if (shape != "ellipse" && shape != "rounded_rectangle")
      refuse("--manhole: shape '" + shape + "' is not ellipse or rounded_rectangle");
    if (comma == std::string::npos)
      refuse("--manhole: expected SHAPE,W,H,CENTRE_Z_REL[,CORNER_R], got '" + text + "'");
    std::vector<double> v = parse_sim_numbers("--manhole", text.substr(comma + 1), 0,
                                              "SHAPE,W,H,CENTRE_Z_REL[,CORNER_R]");
    if (v.size() != 3 && v.size() != 4)
      refuse("--manhole: expected SHAPE,W,H,CENTRE_Z_REL[,CORNER_R], got '" + text + "'");
    check("--manhole", "W", v[0], 0.05, 5.0);
    check("--manhole", "H", v[1], 0.05, 5.0);
    check("--manhole", "CENTRE_Z_REL", v[2], 0.0, 1.0);
    c.manhole_shape = shape;
    c.manhole_width_m = v[0];
    c.manhole_height_m = v[1];
    c.manhole_centre_z_rel = v[2];
    if (v.size() == 4) {
      if (shape != "rounded_rectangle") refuse("--manhole: CORNER_R needs rounded_rectangle");
      check("--manhole", "CORNER_R", v[3], 0.0, 0.5 * std::min(v[0], v[1]));
      c.manhole_corner_radius_m = v[3];
    }
  }
  if (o.stiffener_size && !o.stiffeners) refuse("--stiffener-size needs --stiffeners");
  if (o.stiffeners) {
    std::string rest = *o.stiffeners;
    c.stiffeners.clear();
    for (;;) {
      const auto comma = rest.find(',');
      const std::string item = rest.substr(0, comma);
      const auto colon = item.find(':');
      SimStiffener st;
      st.wall = colon == std::string::npos ? -1 : sim_wall_index(item.substr(0, colon));
      if (st.wall < 0)
        refuse("--stiffeners: '" + item + "' is not WALL:POSITION with WALL left, right, top or bottom");
      st.position_m = parse_sim_numbers("--stiffeners", item.substr(colon + 1), 1, "WALL:POSITION")[0];
      c.stiffeners.push_back(st);
      if (comma == std::string::npos) break;
      rest = rest.substr(comma + 1);
    }
    if (o.stiffener_size) {
      const std::vector<double> v = parse_sim_numbers("--stiffener-size", *o.stiffener_size, 2, "H,T");
      check("--stiffener-size", "H", v[0], 0.01, 0.5);
      check("--stiffener-size", "T", v[1], 0.002, 0.05);
      c.stiffener_height_m = v[0];
      c.stiffener_thickness_m = v[1];
    }
  }
  check("--gradient-pct", o.gradient_pct, -10.0, 10.0);
  check("--cross-fall-deg", o.cross_fall_deg, -10.0, 10.0);
  if (o.curve_radius && *o.curve_radius != 0.0 &&
      !(std::abs(*o.curve_radius) >= 50.0 && std::abs(*o.curve_radius) <= 1e6))
    refuse("--curve-radius " + std::to_string(*o.curve_radius) +
           " must be 0 (straight) or between 50 and 1000000 m in size (sign: + left, - right)");
  if (o.curve_radius) c.curve_radius_m = *o.curve_radius;
  if (o.gradient_pct) c.gradient_pct = *o.gradient_pct;
  if (o.cross_fall_deg) c.cross_fall_deg = *o.cross_fall_deg;
  if (o.transition) {
    if (c.curve_radius_m == 0.0) refuse("--transition needs --curve-radius");
    const std::vector<double> v = parse_sim_numbers("--transition", *o.transition, 2, "START,LENGTH");
    check("--transition", "START", v[0], -1000.0, 10000.0);
    check("--transition", "LENGTH", v[1], 0.1, 1000.0);
    c.transition_start_m = v[0];
    c.transition_m = v[1];
  }
  if (o.vertical_radius && *o.vertical_radius != 0.0 &&
      !(std::abs(*o.vertical_radius) >= 200.0 && std::abs(*o.vertical_radius) <= 1e6))
    refuse("--vertical-radius " + std::to_string(*o.vertical_radius) +
           " must be 0 (constant gradient) or between 200 and 1000000 m in size (sign: + sag, - crest)");
  if (o.vertical_radius) c.vertical_radius_m = *o.vertical_radius;
  if (o.walk_pose && !o.walk && !o.girder) refuse("--walk-pose needs --walk");
  if (!o.walk && o.girder) {
    // The whole girder, one stop per frame, through every manhole.
    SimWalk w;
    w.start_x_m = std::min(0.5, 0.5 * *o.girder);
    w.end_x_m = std::max(w.start_x_m, *o.girder - 0.5);
    w.stops = c.frames;
    w.pose = SimCameraPose{0.0, 0.5, 0.0, 0.0, 0.0};
    w.through_openings = true;
    c.walk = w;
  }
  if (o.walk_pose && !o.walk) {
    const std::vector<double> p =
        parse_sim_numbers("--walk-pose", *o.walk_pose, 3, "Y_REL,Z_REL,PITCH_DEG");
    check("--walk-pose", "Y_REL", p[0], -0.5, 0.5);
    check("--walk-pose", "Z_REL", p[1], 0.0, 1.0);
    check("--walk-pose", "PITCH_DEG", p[2], -60.0, 60.0);
    c.walk->pose.y_rel = p[0];
    c.walk->pose.z_rel = p[1];
    c.walk->pose.pitch_deg = p[2];
  }
  if (o.walk) {
    SimWalk w = parse_sim_walk("--walk", *o.walk);
    check("--walk", "FROM", w.start_x_m, -1000.0, 1000.0);
    check("--walk", "TO", w.end_x_m, -1000.0, 1000.0);
    if (w.stops > c.frames)
      refuse("--walk: " + std::to_string(w.stops) +
             " stops need at least as many frames (--frames is " + std::to_string(c.frames) + ")");
    w.pose = SimCameraPose{0.0, 0.5, 0.0, 0.0, 0.0};
    if (o.walk_pose) {
      const std::vector<double> p =
          parse_sim_numbers("--walk-pose", *o.walk_pose, 3, "Y_REL,Z_REL,PITCH_DEG");
      check("--walk-pose", "Y_REL", p[0], -0.5, 0.5);
      check("--walk-pose", "Z_REL", p[1], 0.0, 1.0);
      check("--walk-pose", "PITCH_DEG", p[2], -60.0, 60.0);
      w.pose.y_rel = p[0];
      w.pose.z_rel = p[1];
      w.pose.pitch_deg = p[2];
    }
    w.through_openings = o.girder.has_value();
    c.walk = w;
  }
  if (o.look_back && !c.walk) refuse("--look-back needs --walk or --girder");
  if (o.look_back) c.walk->look_back = true;
}

void run(const SimulateOptions& o, CliContext& ctx) {
  SimConfig c = SimConfig::from_preset(o.preset);
  check("--width", o.width, 0.3, 5.0);
  check("--height", o.height, 0.3, 5.0);
  if (o.frames) check("--frames", static_cast<double>(*o.frames), 1, 100000);
  check("--distance-to-manhole", o.distance, 0.5, 50.0);
  if (o.seed) check("--seed", static_cast<double>(*o.seed), 0, 4294967295.0);
  check("--noise-scale", o.noise_scale, 0.0, 10.0);
  check("--dropout-scale", o.dropout_scale, 0.0, 100.0);
  check("--roll", o.roll, -60.0, 60.0);
  check("--pitch", o.pitch, -60.0, 60.0);
  check("--yaw", o.yaw, -60.0, 60.0);
  if (o.width) c.width_m = *o.width;
  if (o.height) c.height_m = *o.height;
  if (o.frames) c.frames = *o.frames;
  if (o.distance) c.distance_to_manhole_m = *o.distance;
  if (o.seed) c.seed = static_cast<unsigned>(*o.seed);
  c.rgb_format = o.rgb_format;
  if (o.noise_scale) c.noise_scale = *o.noise_scale;
  if (o.dropout_scale) c.dropout_scale = *o.dropout_scale;
  if (o.roll) c.roll_deg = *o.roll;
  if (o.pitch) c.pitch_deg = *o.pitch;
  if (o.yaw) c.yaw_deg = *o.yaw;
  if (!o.arm.empty()) c.arm_preset = o.arm;
  check("--sag", o.sag, 0.0, 10.0);
  if (o.sag) c.arm_sag_deg_per_m = *o.sag;
  if (!o.noise_model.empty()) c.noise_model = o.noise_model;
  if (o.drift) {
    const std::vector<double> d = parse_sim_numbers("--drift", *o.drift, 2, "MM,DEG");
    check("--drift", "MM", d[0], 0.0, 100.0);
    check("--drift", "DEG", d[1], 0.0, 5.0);
    c.drift_translation_mm_per_sqrt_m = d[0];
    c.drift_rotation_deg_per_sqrt_m = d[1];
  }
  check("--imu", o.imu, 0.0, 10.0);
  if (o.imu) c.imu_gravity_deg = *o.imu;
  apply_layout(o, c);
  c.validate();  // combinations (e.g. manhole opening vs. a small width)

  const SimProgress progress = [&](int i, int n, const std::string& depth_path) {
    if (!o.quiet) std::cout << "frame " << (i + 1) << "/" << n << ": " << depth_path << "\n";
  };
  if (o.format == "tum")
    write_sim_tum_sequence(o.out_dir, c, progress, [](const std::string& line) {
      std::cerr << "tunnelmap-cli: note: " << line << "\n";
    });
  else
    write_sim_dataset(o.out_dir, c, progress);
  std::cout << "wrote " << c.frames << " simulated " << c.preset << " frames (";
  if (c.sections.empty()) std::cout << c.width_m << " x " << c.height_m << " m";
  else std::cout << c.sections.size() << (c.sections.size() == 1 ? " section" : " sections");
  std::cout << ", seed " << c.seed << ") to " << o.out_dir << "\n";
  ctx.exit_code = 0;
}

}  // namespace

void add_simulate_command(CLI::App& app, CliContext& ctx) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand(
      "simulate", "Write a simulated tunnel dataset (depth, RGB, ground-truth surfaces)");
  sub->add_option("OUT_DIR", opt->out_dir, "Output folder (new, empty, or an existing dataset)")
      ->required();
  sub->add_option("--preset", opt->preset, "lab (Experiment 1) or field (Experiment 2)")
      ->check(CLI::IsMember({"lab", "field"}));
  sub->add_option("--width", opt->width, "Tunnel width W in metres (outermost surfaces)");
  sub->add_option("--height", opt->height, "Tunnel height H in metres (outermost surfaces)");
  sub->add_option("--frames", opt->frames, "Total number of frames");
  sub->add_option("--distance-to-manhole", opt->distance,
                  "Put every frame this far from the manhole plate (metres)");
  sub->add_option("--seed", opt->seed, "Random seed (same seed = identical dataset)");
  sub->add_option("--noise-scale", opt->noise_scale, "Multiplies the depth noise (0 = exact)");
  sub->add_option("--dropout-scale", opt->dropout_scale,
                  "Multiplies the dropout probabilities (0 = none)");
  sub->add_option("--roll", opt->roll, "Extra camera roll for every pose (degrees)");
  sub->add_option("--pitch", opt->pitch, "Extra camera pitch for every pose (degrees)");
  sub->add_option("--yaw", opt->yaw, "Extra camera yaw for every pose (degrees)");
  sub->add_option("--rgb-format", opt->rgb_format, "Colour images as png (lossless) or jpg (small)")
      ->check(CLI::IsMember({"png", "jpg"}));
  sub->add_option("--arm", opt->arm,
                  "Eye-in-hand arm preset (inchworm7): frames get joints, not poses")
      ->check(CLI::IsMember({"inchworm7"}));
  sub->add_option("--sag", opt->sag, "Arm link sag in degrees per metre of reach (with --arm)");
  sub->add_option("--sections", opt->sections,
                  "Sections of changing size along the tunnel: L:WxH,L:WxH,... (metres)");
  sub->add_option("--sections-start", opt->sections_start,
                  "World X where the first section begins (metres, default 0)");
  sub->add_option("--diaphragms", opt->diaphragms,
                  "Manhole diaphragms at these world X positions: X1,X2,... (metres)");
  sub->add_option("--walk", opt->walk,
                  "Walk the camera along the tunnel: FROM,TO,STOPS (metres, stations)");
  sub->add_option("--walk-pose", opt->walk_pose,
                  "Camera pose at every walk station: Y_REL,Z_REL,PITCH_DEG (default 0,0.5,0)");
  sub->add_flag("--look-back", opt->look_back,
               "With --walk or --girder: the stop nearest the middle of each compartment past a "
               "plate looks back along the girder (sees the stretch the plate hid)");
  sub->add_option("--imu,--imu-gravity-deg", opt->imu,
                  "An IMU on the camera: each frame's \"gravity\" (where things fall, camera frame), "
                  "tilted by DEG degrees (1 sigma) about each axis across it; drift does not reach it");
  sub->add_option("--drift", opt->drift,
                  "Odometry drift MM,DEG: random walk of MM millimetres and DEG degrees per "
                  "sqrt(metre) travelled, per axis; \"pose\" drifts, \"pose_true\" is the truth");
  sub->add_option("--noise-model", opt->noise_model,
                  "Depth noise: structured_light (default: disparity quantisation, error ~ z^2) or "
                  "tof (error linear in z, flying pixels at depth edges)")
      ->check(CLI::IsMember({"structured_light", "tof"}));
  sub->add_option("--girder", opt->girder,
                  "A whole girder of this length (metres): start wall at 0, end wall at L; "
                  "without --walk, one stop per frame from 0.5 to L-0.5 through the manholes");
  sub->add_option("--diaphragm-spacing", opt->diaphragm_spacing,
                  "With --girder: diaphragms every S metres (at S, 2S, ... short of L)");
  sub->add_option("--manhole", opt->manhole,
                  "Every plate's opening: SHAPE,W,H,CENTRE_Z_REL[,CORNER_R] with SHAPE ellipse or "
                  "rounded_rectangle (metres; centre height / section height; default "
                  "ellipse,0.45,0.70,0.5; corner radius 0.1)");
  sub->add_option("--stiffeners", opt->stiffeners,
                  "Longitudinal flat-bar stiffeners WALL:POS,... (WALL left|right|top|bottom; POS "
                  "across the wall: height above the floor, or y with left positive; metres)");
  sub->add_option("--stiffener-size", opt->stiffener_size,
                  "Stiffener height out of the wall and thickness H,T (metres, default 0.1,0.01)");
  sub->add_option("--curve-radius", opt->curve_radius,
                  "Horizontal curve radius in metres (0 = straight, > 0 left, < 0 right; |R| >= 50)");
  sub->add_option("--gradient-pct", opt->gradient_pct,
                  "Longitudinal gradient in percent (> 0 rises along the girder; -10..10)");
  sub->add_option("--cross-fall-deg", opt->cross_fall_deg,
                  "Cross-fall: roll of the cross-section in degrees (> 0 lifts the left wall; -10..10)");
  sub->add_option("--transition", opt->transition,
                  "Transition curve START,LENGTH (metres): straight up to station START, then the "
                  "curvature grows evenly over LENGTH (>= 0.1) to that of --curve-radius");
  sub->add_option("--vertical-radius", opt->vertical_radius,
                  "Vertical curve radius in metres (0 = constant gradient, > 0 sag, < 0 crest; "
                  "|R| >= 200): the gradient changes by 1/R per metre from --gradient-pct at station 0");
  sub->add_option("--format", opt->format,
                  "Output layout: dataset (dataset.json, default) or tum (TUM RGB-D: depth.txt, "
                  "rgb.txt, groundtruth.txt)")
      ->check(CLI::IsMember({"dataset", "tum"}));
  sub->add_flag("--quiet", opt->quiet, "Print only the summary line");
  sub->callback([opt, &ctx] { run(*opt, ctx); });
}

}  // namespace tunnelmap::cli
