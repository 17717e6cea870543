// `tunnelmap-cli simulate OUT_DIR`: writes a simulated tunnel dataset (core/sim).
#include <iostream>
#include <memory>
#include <sstream>

#include "app/cli/commands.h"
#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"
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
  std::string arm;                 // robot preset: joints instead of poses
  std::optional<double> sag;       // arm link sag, deg per metre of reach
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
  c.validate();  // combinations (e.g. manhole opening vs. a small width)

  write_sim_dataset(o.out_dir, c, [&](int i, int n, const std::string& depth_path) {
    if (!o.quiet) std::cout << "frame " << (i + 1) << "/" << n << ": " << depth_path << "\n";
  });
  std::cout << "wrote " << c.frames << " simulated " << c.preset << " frames (" << c.width_m
            << " x " << c.height_m << " m, seed " << c.seed << ") to " << o.out_dir << "\n";
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
  sub->add_flag("--quiet", opt->quiet, "Print only the summary line");
  sub->callback([opt, &ctx] { run(*opt, ctx); });
}

}  // namespace tunnelmap::cli
