// `tunnelmap-cli planes INPUT`: plane extraction only (cloud, normals, PG&C), with timings as
// medians over --repeat runs and an optional 16-bit label image.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "app/cli/commands.h"
#include "app/cli/input_options.h"
#include "app/cli/output_options.h"
#include "core/io/frame_source.h"
#include "core/engine/run_engine.h"
#include "core/report/results_json.h"
#include "core/util/atomic_file.h"
#include "core/util/image_file.h"
#include "core/util/error.h"

namespace tunnelmap::cli {

namespace {
struct PlanesOptions {
  InputOptions in;
  std::string json_path;
  std::string labels_path;
  int repeat = 1;
  int threads = 0;  // worker threads for sequences (0 = all cores)
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// For sequences, "labels.png" becomes "labels_000003.png".
std::string labels_name(const std::string& path, std::size_t index, std::size_t count) {
  if (count <= 1) return path;
  namespace fs = std::filesystem;
  const fs::path p(path);
  char suffix[16];
  std::snprintf(suffix, sizeof suffix, "_%06zu", index);
  return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

void write_labels(const std::string& path, const PlaneSegments& planes) {
  cv::Mat img(planes.height, planes.width, CV_16UC1);
  for (int v = 0; v < planes.height; ++v)
    for (int u = 0; u < planes.width; ++u)
      img.at<std::uint16_t>(v, u) =
          static_cast<std::uint16_t>(std::min(65535, planes.labels[static_cast<std::size_t>(v) * planes.width + u]));
  write_image_file(path, img);
}

int run_planes(const PlanesOptions& o) {
  if (o.repeat < 1 || o.repeat > 10000) throw ParameterError("--repeat must be between 1 and 10000");
  if (!o.labels_path.empty() && std::filesystem::path(o.labels_path).extension() != ".png")
    throw ParameterError("--labels must name a .png file");
  const Parameters params = o.in.parameters();
  check_outputs({o.in.input, o.in.params_file}, {o.json_path, o.labels_path});
  auto source = open_input(o.in.input, o.in.read_options());
  // Cloud, normals and planes (--repeat times, median timings) in the worker threads; printing
  // and the label images in frame order.
  const int repeat = o.repeat;
  auto work = [params, repeat](const DepthFrame& frame, FrameResult& r) {
    check_frame_size(frame, normal_options(params));  // InputError naming the file
    OrganizedCloud& cloud = r.cloud;
    // Every stage's time (cloud, normals, planes and the planes' own sub-stages: grow, refine,
    // edge_on, contours), reported as the median over the repeats.
    std::map<std::string, std::vector<double>> samples;
    for (int k = 0; k < repeat; ++k) {
      cloud.timings_ms.clear();
      const auto start = std::chrono::steady_clock::now();
      {
        StageTimer t(cloud.timings_ms, "cloud");
        build_cloud(frame, cloud_options(params), cloud, r.scratch.cloud);
      }
      const GrowOptions grow = grow_options(params);
      if (needs_point_normals(grow)) estimate_normals(normal_options(params), cloud, r.scratch.normals);
      else cloud.timings_ms["normals"] = 0.0;  // not needed: the cell-based order reads points only
      extract_planes(cloud, grow, r.planes, r.scratch.planes);
      samples["total"].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      for (const StageTimings* stages : {&cloud.timings_ms, &r.planes.timings_ms})
        for (const auto& [stage, ms] : *stages) samples[stage].push_back(ms);
    }
    r.timings_ms.clear();
    for (auto& [stage, values] : samples) r.timings_ms[stage] = median(values);
  };
  RunSettings settings;
  settings.params = params;
  settings.threads = o.threads;
  nlohmann::json frames = nlohmann::json::array();
  Progress progress(source->size());
  run_frames(*source, work, settings, [&](SequenceFrame& f) {
    if (!f.ok()) std::rethrow_exception(f.error);  // one-line error, exit 3, as before
    const std::size_t i = f.index;
    const PlaneSegments& planes = f.result.planes;
    const StageTimings& timings = f.result.timings_ms;
    frames.push_back(planes_frame_json(i, f.frame.source, planes, timings));
    std::printf("[%zu] %s: %zu planes, normals %.2f ms, planes %.2f ms, total %.2f ms%s\n", i,
                source->describe(i).c_str(), planes.planes.size(), timings.at("normals"),
                timings.at("planes"), timings.at("total"),
                o.repeat > 1 ? (" (median of " + std::to_string(o.repeat) + ")").c_str() : "");
    if (!o.labels_path.empty()) write_labels(labels_name(o.labels_path, i, source->size()), planes);
    return true;
  }, [&progress](std::size_t done, std::size_t) { progress.step(done); });
  if (!o.json_path.empty()) {
    nlohmann::json doc = {{"tool", "tunnelmap"}, {"version", TUNNELMAP_VERSION}, {"method", "pgc"},
                          {"input", o.in.input}, {"params", params.to_json()}, {"repeat", o.repeat},
                          {"frames", frames}};
    write_file_atomically(o.json_path, [&](std::ostream& out) { out << doc.dump(2) << "\n"; });
  }
  return 0;
}
}  // namespace

void add_planes_command(CLI::App& app, CliContext& ctx) {
  static PlanesOptions o;
  auto* cmd = app.add_subcommand("planes", "Extract planes only (PG&C) and time the stages");
  add_input_options(cmd, o.in);
  add_output_option(cmd, "--json", o.json_path, "Write the planes and timings as JSON");
  add_output_option(cmd, "--labels", o.labels_path, "Write the plane label image (16-bit PNG; _NNNNNN per frame for sequences)");
  cmd->add_option("--repeat", o.repeat, "Run N times and report median timings");
  cmd->add_option("--threads", o.threads,
                  "Worker threads for sequences (default 0 = all cores; use 1 for undisturbed timings)")
      ->check(CLI::Range(0, 256));
  cmd->callback([&ctx] { ctx.exit_code = run_planes(o); });
}

}  // namespace tunnelmap::cli
