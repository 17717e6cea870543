// `tunnelmap-cli detect INPUT`: the whole pipeline on a frame or a sequence, one line per frame
// and a summary; optional JSON and CSV results and the tunnel map as a PLY mesh.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <tuple>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "app/cli/output_options.h"
#include "core/export/map_ply.h"
#include "core/engine/run_engine.h"
#include "core/io/frame_source.h"
#include "core/report/results_csv.h"
#include "core/report/results_json.h"
#include "core/util/atomic_file.h"
#include "sensors/openni/device_frame_source.h"

namespace tunnelmap::cli {

namespace {
struct DetectOptions {
  InputOptions in;
  std::string json_path;
  std::string csv_path;
  std::string ply_path;
  bool quiet = false;
  std::string method = "pgc";  // pgc | ransac | qhull
  std::string device;  // live OpenNI2 device URI ("default" = the first one)
  int frames = 30;     // frames to process from a live device
  int threads = 0;     // worker threads for sequences (0 = all cores)
};

void print_frame_line(std::size_t index, const std::string& what, const FrameResult& r) {
  const TunnelMap& m = r.map;
  if (m.status == TunnelStatus::Partial) {
    // "partial: height from context", then the values that are known.
    std::string dims;
    for (const auto& [name, src, value] :
         {std::tuple{"width", m.width_source, m.width_m}, std::tuple{"height", m.height_source, m.height_m}}) {
      char buf[64];
      if (src == DimensionSource::Unseen)
        std::snprintf(buf, sizeof buf, " %s unknown", name);
      else
        std::snprintf(buf, sizeof buf, " %s %.4f m%s%s", name, value,
                      src == DimensionSource::Measured ? "" : " from ",
                      src == DimensionSource::Measured ? "" : dimension_source_name(src));
      dims += buf;
    }
    std::printf("[%zu] %s: partial: %s; tunnel%s, %zu planes, %.1f ms\n", index, what.c_str(), m.reason.c_str(),
                dims.c_str(), r.planes.planes.size(), r.timings_ms.at("total"));
  } else if (m.detected)
    std::printf("[%zu] %s: tunnel width %.4f m height %.4f m, %zu planes, %.1f ms\n", index, what.c_str(),
                m.width_m, m.height_m, r.planes.planes.size(), r.timings_ms.at("total"));
  else
    std::printf("[%zu] %s: no tunnel (%s%s%s), %zu planes, %.1f ms\n", index, what.c_str(), status_name(m.status),
                m.reason.empty() ? "" : ": ", m.reason.c_str(), r.planes.planes.size(),
                r.timings_ms.at("total"));
}

// Means over the measured values only, each with the number of frames it covers.
void print_summary_line(const DetectionSummary& s) {
  std::printf("summary: %d/%d frames detected", s.detected, s.frames);
  const auto stat = [](const char* name, int n, const std::optional<double>& mean, const std::optional<double>& sd) {
    if (!mean) return std::printf(", %s unknown (measured in no frame)", name), void();
    std::printf(", %s %.4f m", name, *mean);
    if (sd) std::printf(" (sigma %.4f)", *sd);
    std::printf(" over %d frame%s", n, n == 1 ? "" : "s");
  };
  stat("width", s.width_frames, s.width_mean_m, s.width_std_m);
  stat("height", s.height_frames, s.height_mean_m, s.height_std_m);
  if (s.width_abs_error_mean_m || s.height_abs_error_mean_m) {
    const auto mm = [](const std::optional<double>& v) { return v ? *v * 1000 : std::nan(""); };
    std::printf(", mean abs error %.1f / %.1f mm vs ground truth", mm(s.width_abs_error_mean_m),
                mm(s.height_abs_error_mean_m));
  }
  if (s.total_ms_median) std::printf(", median %.1f ms/frame", *s.total_ms_median);
  std::printf("\n");
}

int run_detect(const DetectOptions& o) {
  RunSettings settings;  // parameter errors before any reading
  settings.params = o.in.parameters();
  settings.camera_up = o.in.camera_up();
  settings.method = parse_method(o.method);
  settings.threads = o.threads;
  check_outputs({o.in.input, o.in.params_file}, {o.json_path, o.csv_path, o.ply_path});
  const bool live = !o.device.empty();
  settings.live = live;
  // One line each (CLI::RequiredError appends " is required" itself).
  if (!live && o.in.input.empty()) throw CLI::RequiredError("detect: INPUT or --device URI");
  if (live && !o.in.input.empty()) throw CLI::ValidationError("detect", "give INPUT or --device URI, not both");
  std::unique_ptr<FrameSource> source;
  if (live)
    source = std::make_unique<openni2::DeviceFrameSource>(o.device, static_cast<std::size_t>(std::max(o.frames, 0)),
                                                          o.in.read_options());
  else
    source = open_input(o.in.input, o.in.read_options());
  // Live input: frame rate and latency (frame in hand -> result) as the pipeline keeps up, from
  // the first frame on (a camera's start-up is not the pipeline's rate).
  using clock = std::chrono::steady_clock;
  clock::time_point first_frame, last_frame;
  std::vector<double> latencies_ms;
  DetectionSummary summary;
  if (const Dataset* ds = source->dataset()) {
    summary.gt_width_m = ds->gt_width_m;
    summary.gt_height_m = ds->gt_height_m;
  }
  RunEngine engine(settings, source.get());

  DetectionDocument doc;
  doc.method = settings.method;
  doc.input = live ? o.device : o.in.input;
  doc.params = settings.params;
  std::optional<TunnelMap> last_map;
  Eigen::Isometry3d last_pose = Eigen::Isometry3d::Identity();
  Progress progress(source->size());
  engine.run(*source, [&](SequenceFrame& f) {
    if (!f.ok()) std::rethrow_exception(f.error);  // one-line error, exit 3, as before
    const std::size_t i = f.index;
    const FrameResult& result = f.result;
    if (i == 0) first_frame = f.loaded_at;
    last_frame = f.loaded_at;
    latencies_ms.push_back(std::chrono::duration<double, std::milli>(clock::now() - f.loaded_at).count());
    doc.frames.push_back(detection_record(static_cast<int>(i), f.frame.source, result, settings.method));
    summary.add(doc.frames.back());
    if (result.map.detected) {
      last_map = result.map;
      last_pose = f.frame.pose.value_or(Eigen::Isometry3d::Identity());
    }
    if (!o.quiet) print_frame_line(i, source->describe(i), result);
    return true;
  }, [&progress](std::size_t done, std::size_t) { progress.step(done); });
  summary.finish();
  print_summary_line(summary);
  if (live && !latencies_ms.empty()) {
    const double seconds = std::chrono::duration<double>(last_frame - first_frame).count();
    const double fps = seconds > 0 ? (latencies_ms.size() - 1) / seconds : 0.0;  // frame intervals
    std::sort(latencies_ms.begin(), latencies_ms.end());
    std::printf("live: %zu frames in %.2f s = %.1f fps, latency median %.1f ms, max %.1f ms\n", latencies_ms.size(),
                seconds, fps, latencies_ms[latencies_ms.size() / 2], latencies_ms.back());
  }

  doc.summary = summary;
  if (!o.json_path.empty()) write_detection_json(o.json_path, doc);
  if (!o.csv_path.empty()) write_detection_csv(o.csv_path, doc);
  if (!o.ply_path.empty()) {
    if (last_map)
      write_map_ply(o.ply_path, *last_map, settings.params.to_json(), last_pose);
    else
      std::fprintf(stderr, "tunnelmap-cli: no tunnel detected in any frame: %s not written\n",
                   o.ply_path.c_str());
  }
  return 0;
}
}  // namespace

void add_detect_command(CLI::App& app, CliContext& ctx) {
  static DetectOptions o;
  auto* cmd = app.add_subcommand("detect", "Detect the tunnel in a depth frame, PCD, dataset, .oni recording or live device");
  add_input_options(cmd, o.in, false);
  cmd->add_option("--device", o.device, "Live OpenNI2 device URI (see `devices`; \"default\" = the first one)");
  cmd->add_option("--frames", o.frames, "Frames to process from --device (default 30)")->check(CLI::PositiveNumber);
  add_output_option(cmd, "--json", o.json_path, "Write per-frame results and a summary as JSON");
  add_output_option(cmd, "--csv", o.csv_path, "Write one row per frame as CSV (the JSON's main fields)");
  add_output_option(cmd, "--ply", o.ply_path,
                  "Write the tunnel map (last detected frame, world frame when posed) as a binary PLY mesh");
  cmd->add_option("--threads", o.threads, "Worker threads for sequences (default 0 = all cores; 1 = serial)")
      ->check(CLI::Range(0, 256));
  cmd->add_flag("--quiet,-q", o.quiet, "Only print the summary line");
  cmd->add_option("--method", o.method, "pgc (the paper's PG&C), ransac (R&L baseline) or qhull (convex-hull baseline)")
      ->capture_default_str();
  cmd->callback([&ctx] { ctx.exit_code = run_detect(o); });
}

}  // namespace tunnelmap::cli
