// tunnelmap_plane_recall: plane recall and precision on simulated frames, with a
// breakdown of the missed surfaces (scripts/recall.sh writes docs/recall.md with it).
// Every preset x grid step runs the full pipeline on the simulator's frames of each seed
// (seed 100*s + 1 for lab, 100*s + 2 for field, s = 1..--seeds) and scores the planes against
// the true surface ids with SegmentationOptions::by_size(grow.min_points, grow.min_area_m2).
// Exit codes: 0 ok, 2 bad usage, 3 unreadable preset / unwritable output.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/plane_recall_normals.h"
#include "bench/plane_recall_tally.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/atomic_file.h"
#include "core/util/build_paths.h"
#include "core/util/error.h"

using namespace tunnelmap;

namespace {

const char* const kUsage =
    "usage: tunnelmap_plane_recall [--seeds N] [--stride K] [--presets lab,field] [--grid-steps 1,2]\n"
    "         [--set KEY=VALUE]... [--presets-dir DIR] [--csv FILE] [--markdown FILE]\n"
    "  --seeds N         simulator seeds per preset (default 4)\n"
    "  --stride K        every K-th frame of each seed (default 1 = all 30)\n"
    "  --presets LIST    simulator + parameter presets, lab and/or field (default lab,field)\n"
    "  --grid-steps LIST grow.grid_step values to run (default 1,2)\n"
    "  --set KEY=VALUE   parameter on top of each preset (repeatable)\n"
    "  --presets-dir DIR preset JSON files (default: the source tree's resources/presets)\n"
    "  --csv FILE        one row per true surface and frame\n"
    "  --markdown FILE   the report (also printed on stdout)\n"
    "  --normal-errors FILE  the cell order's block normals against the true surfaces, by range\n"
    "                    (needs grow.cell_px > 0)\n"
    "  --max-normal-error-ratio R  exit 1 when, in a range band of at least 100 cells, the median\n"
    "                    block-normal error exceeds R times its claimed standard error (1.18 when right)\n"
    "  --min-recall R    exit 1 when any preset x grid step has recall below R (0..1)\n"
    "  --min-precision P exit 1 when any preset x grid step has precision below P (0..1)\n";

const std::string kDefaultPresetsDir = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  int seeds = 4;
  int stride = 1;
  std::vector<std::string> presets{"lab", "field"};
  std::vector<int> grid_steps{1, 2};
  std::vector<std::string> sets;
  std::string presets_dir = kDefaultPresetsDir;
  std::string csv, markdown, normal_errors;
  double min_recall = 0.0, min_precision = 0.0;  // regression limits (0 = none)
  double max_normal_error_ratio = 0.0;            // 0 = none
};

double parse_fraction(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double v = -1;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(v >= 0.0 && v <= 1.0))
    throw UsageError(option + ": '" + text + "' is not a fraction between 0 and 1");
  return v;
}

int parse_int(const std::string& option, const std::string& text, int lo, int hi) {
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(text, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != text.size() || v < lo || v > hi)
    throw UsageError(option + " expects an integer from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got '" + text + "'");
  return static_cast<int>(v);
}

std::vector<std::string> split_list(const std::string& option, const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) throw UsageError(option + " expects a comma-separated list, got '" + text + "'");
    items.push_back(item);
  }
  if (items.empty()) throw UsageError(option + " expects a comma-separated list, got '" + text + "'");
  return items;
}

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i], value;
    const auto eq = arg.find('=');
    const bool inline_value = arg.rfind("--", 0) == 0 && eq != std::string::npos;
    if (inline_value) value = arg.substr(eq + 1), arg = arg.substr(0, eq);
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    static const char* const kValued[] = {"--seeds", "--stride", "--presets", "--grid-steps",
                                          "--set", "--presets-dir", "--csv", "--markdown", "--normal-errors",
                                          "--max-normal-error-ratio", "--min-recall", "--min-precision"};
    if (std::find(std::begin(kValued), std::end(kValued), arg) == std::end(kValued))
      throw UsageError(arg.rfind("-", 0) == 0 ? "unknown option '" + arg + "' (see --help)"
                                              : "unexpected argument '" + arg + "'");
    if (!inline_value) {
      if (i + 1 >= argc) throw UsageError(arg + " expects a value");
      value = argv[++i];
    }
    if (arg == "--seeds") {
      o.seeds = parse_int(arg, value, 1, 1000);
    } else if (arg == "--stride") {
      o.stride = parse_int(arg, value, 1, 1000);
    } else if (arg == "--presets") {
      o.presets = split_list(arg, value);
      for (const auto& p : o.presets)
        if (p != "lab" && p != "field")
          throw UsageError("--presets: unknown preset '" + p + "' (expected lab or field)");
    } else if (arg == "--grid-steps") {
      o.grid_steps.clear();
      for (const auto& s : split_list(arg, value)) o.grid_steps.push_back(parse_int(arg, s, 1, 1000));
      for (int s : o.grid_steps) Parameters().set("grow.grid_step", s);  // its range, as ParameterError
    } else if (arg == "--set") {
      if (value.rfind("grow.grid_step=", 0) == 0) throw UsageError("--set grow.grid_step: use --grid-steps");
      Parameters().set_from_string(value);  // unknown key or bad value: ParameterError
      o.sets.push_back(value);
    } else if (arg == "--presets-dir") {
      o.presets_dir = value;
    } else if (arg == "--csv") {
      o.csv = value;
    } else if (arg == "--normal-errors") {
      o.normal_errors = value;
    } else if (arg == "--max-normal-error-ratio") {
      std::size_t used = 0;
      try {
        o.max_normal_error_ratio = std::stod(value, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != value.size() || !(o.max_normal_error_ratio > 0 && o.max_normal_error_ratio < 1e6))
        throw UsageError(arg + ": '" + value + "' is not a positive ratio");
    } else if (arg == "--min-recall") {
      o.min_recall = parse_fraction(arg, value);
    } else if (arg == "--min-precision") {
      o.min_precision = parse_fraction(arg, value);
    } else {  // --markdown
      o.markdown = value;
    }
  }
  if (o.max_normal_error_ratio > 0 && o.normal_errors.empty())
    throw UsageError("--max-normal-error-ratio needs --normal-errors FILE");
  return o;
}

unsigned sim_seed(const std::string& preset, int s) { return 100u * s + (preset == "lab" ? 1u : 2u); }

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& item : items) s += (s.empty() ? "" : ", ") + item;
  return s;
}

std::string settings_line(const Options& o) {
  std::vector<std::string> steps, per_preset;
  for (int g : o.grid_steps) steps.push_back(std::to_string(g));
  for (const auto& preset : o.presets) {
    std::vector<std::string> seeds;
    for (int s = 1; s <= o.seeds; ++s) seeds.push_back(std::to_string(sim_seed(preset, s)));
    per_preset.push_back(preset + " seeds " + join(seeds));
  }
  const std::string dir = o.presets_dir == kDefaultPresetsDir ? "resources/presets" : o.presets_dir;
  const std::string frames = o.stride == 1 ? "every frame" : "one frame in " + std::to_string(o.stride);
  std::string seeds;
  for (const auto& p : per_preset) seeds += p + "; ";
  return "presets " + join(o.presets) + " (" + dir + "); " + seeds + frames +
         " of each seed's sequence; grid steps " + join(steps) + "; " +
         (o.sets.empty() ? "no --set." : "--set " + join(o.sets) + ".");
}

// Per-surface rows of --csv.
const char* const kCsvHeader =
    "preset,grid_step,seed,frame,surface_id,surface,wall,zone,truth_pixels,visible_pixels,normal_pixels,"
    "area_m2,mean_depth_m,incidence_deg,counted,found,best_plane,best_plane_pixels,best_plane_share,labelled_pixels\n";

void append_csv_row(std::string& csv, const recall::RunTally& t, unsigned seed, int frame, const SurfaceDetail& d,
                    const SimSurface* surface, long normal_pixels) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "%s,%d,%u,%d,%d,%s,%s,%s,%ld,%ld,%ld,%.5f,%.3f,%.2f,%d,%d,%d,%ld,%.4f,%ld\n",
                t.preset.c_str(), t.grid_step, seed, frame, d.id, surface ? surface->name.c_str() : "?",
                surface ? surface->wall.c_str() : "?", surface ? surface->zone.c_str() : "?", d.truth_pixels, d.pixels,
                normal_pixels, d.area_m2, d.mean_depth_m, d.incidence_deg, int(d.counted), int(d.found), d.best_plane,
                d.best_plane_pixels, d.best_plane_share, d.labelled_pixels);
  csv += buf;
}

// One preset x grid step over every seed and frame.
recall::RunTally run(const Options& o, const std::string& preset, int grid_step, std::string* csv,
                     recall::NormalErrors* normal_errors) {
  Parameters params;
  params.load_json_file(o.presets_dir + "/" + preset + ".json");
  for (const auto& s : o.sets) params.set_from_string(s);
  params.set("grow.grid_step", grid_step);
  const Pipeline pipeline(params);
  const GrowOptions grow = grow_options(params);
  const SegmentationOptions scoring = SegmentationOptions::by_size(grow.min_points, grow.min_area_m2);
  if (normal_errors && grow.cell_px <= 0)
    throw UsageError("--normal-errors measures the cell order: add --set grow.cell_px=8 (or another size)");

  recall::RunTally t;
  t.preset = preset;
  t.grid_step = grid_step;
  t.min_points = grow.min_points;
  FrameResult result;
  std::vector<SurfaceDetail> details;
  std::vector<long> normal_pixels;
  for (int s = 1; s <= o.seeds; ++s) {
    SimConfig config = SimConfig::from_preset(preset);
    config.seed = sim_seed(preset, s);
    const TunnelSimulator sim(config);
    for (int i = 0; i < sim.frame_count(); i += o.stride) {
      const SimFrame frame = sim.render(i);
      pipeline.run(frame.frame, result);
      t.score += score_segmentation(result.planes, frame.surface_id, result.cloud, scoring, &details);
      if (normal_errors)
        normal_errors->add_frame(result.scratch.planes.cells.grid, result.cloud.width, result.cloud.height,
                                 frame.surface_id, details);
      ++t.frames;
      // Pixels of each surface that carry a normal (the growing's raw material); the cell order
      // computes no per-pixel normals and counts none.
      normal_pixels.assign(65536, 0);
      if (result.cloud.normals.size() == frame.surface_id.size())
        for (std::size_t k = 0; k < frame.surface_id.size(); ++k)
          if (!std::isnan(result.cloud.normals[k].x())) ++normal_pixels[frame.surface_id[k]];
      for (const SurfaceDetail& d : details) {
        const SimSurface* surface = sim.surface(d.id);
        t.add_surface(d, surface ? surface->name : "?", normal_pixels[d.id]);
        if (csv) append_csv_row(*csv, t, config.seed, i, d, surface, normal_pixels[d.id]);
      }
    }
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse_options(argc, argv);
    // Fail now, not after minutes of work.
    if (!o.csv.empty()) check_output_path(o.csv);
    if (!o.markdown.empty()) check_output_path(o.markdown);
    if (!o.normal_errors.empty()) check_output_path(o.normal_errors);
    for (const auto& preset : o.presets) Parameters().load_json_file(o.presets_dir + "/" + preset + ".json");

    std::string csv = kCsvHeader;
    std::vector<recall::RunTally> runs;
    std::vector<recall::NormalErrors> normal_errors;
    for (const auto& preset : o.presets)
      for (int step : o.grid_steps) {
        recall::NormalErrors* errors = nullptr;
        if (!o.normal_errors.empty()) {
          normal_errors.emplace_back();
          normal_errors.back().preset = preset + ", step " + std::to_string(step);
          errors = &normal_errors.back();
        }
        runs.push_back(run(o, preset, step, o.csv.empty() ? nullptr : &csv, errors));
        const recall::RunTally& t = runs.back();
        std::fprintf(stderr, "%s, grid step %d: %ld frames, recall %.4f (%ld / %ld), precision %.4f (%ld / %ld)\n",
                     preset.c_str(), step, t.frames, t.score.recall(), t.score.found_surfaces, t.score.surfaces,
                     t.score.precision(), t.score.correct_planes, t.score.planes);
      }
    const std::string report = recall::markdown_report(runs, settings_line(o));
    std::cout << report;
    if (!o.markdown.empty()) write_file_atomically(o.markdown, [&](std::ostream& out) { out << report; });
    if (!o.csv.empty()) write_file_atomically(o.csv, [&](std::ostream& out) { out << csv; });
    if (!o.normal_errors.empty()) {
      const std::string table = recall::normal_error_report(normal_errors);
      write_file_atomically(o.normal_errors, [&](std::ostream& out) { out << table; });
    }
    int status = 0;
    if (o.max_normal_error_ratio > 0) {
      std::string where;
      const double worst = recall::worst_median_error_ratio(normal_errors, 100, where);
      if (worst > o.max_normal_error_ratio) {
        std::fprintf(stderr, "FAIL: %s median block-normal error %.2f times its standard error > %.2f\n",
                     where.c_str(), worst, o.max_normal_error_ratio);
        status = 1;
      }
    }
    for (const recall::RunTally& t : runs) {
      if (t.score.recall() < o.min_recall) {
        std::fprintf(stderr, "FAIL: %s grid step %d recall %.4f < %.4f\n", t.preset.c_str(), t.grid_step,
                     t.score.recall(), o.min_recall);
        status = 1;
      }
      if (t.score.precision() < o.min_precision) {
        std::fprintf(stderr, "FAIL: %s grid step %d precision %.4f < %.4f\n", t.preset.c_str(), t.grid_step,
                     t.score.precision(), o.min_precision);
        status = 1;
      }
    }
    return status;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "tunnelmap_plane_recall: %s\n", e.what());
    return 2;
  } catch (const ParameterError& e) {
    std::fprintf(stderr, "tunnelmap_plane_recall: %s\n", e.what());
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "tunnelmap_plane_recall: %s\n", e.what());
    return 3;
  }
}
