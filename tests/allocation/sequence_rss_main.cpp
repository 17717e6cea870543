// tunnelmap_sequence_rss: resident memory while SequenceRunner detects the tunnel in a long
// sequence (requirement: peak RSS for 1,000 frames <= 300 MB, flat over time). The input is a
// 30-frame simulated lab dataset on disk, cycled, so every frame is decoded from PNG as in real
// use. Prints RSS at frames 100, 500, 1000 (and the end); exits 1 if the peak exceeds
// --max-peak-mb or RSS grows by more than --max-growth-mb between frame 100 and the end.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/io/frame_source.h"
#include "core/pipeline/sequence_runner.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"
#include "tests/allocation/process_memory.h"

using namespace tunnelmap;
namespace fs = std::filesystem;

using testing::status_mb;

namespace {

// `frames` frames: the inner source's frames over and over.
class CyclingSource : public FrameSource {
 public:
  CyclingSource(std::unique_ptr<FrameSource> inner, std::size_t frames)
      : inner_(std::move(inner)), frames_(frames) {}
  std::size_t size() const override { return frames_; }
  DepthFrame load(std::size_t i) const override { return inner_->load(i % inner_->size()); }
  std::string describe(std::size_t i) const override { return inner_->describe(i % inner_->size()); }
  const Dataset* dataset() const override { return inner_->dataset(); }

 private:
  std::unique_ptr<FrameSource> inner_;
  std::size_t frames_;
};

// Writes the dataset in a child process so that the simulator's buffers never count towards
// this process's peak.
bool write_dataset_in_child(const std::string& dir) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    try {
      SimConfig config = SimConfig::from_preset("lab");
      config.frames = 30;
      config.seed = 7;
      write_sim_dataset(dir, config);
      _exit(0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "simulate: %s\n", e.what());
      _exit(1);
    }
  }
  int status = 0;
  return waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t frames = 1000;
  int threads = 2;
  double max_peak_mb = 300.0, max_growth_mb = 20.0;
  std::string dataset;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool v = i + 1 < argc;
    if (a == "--frames" && v) frames = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--threads" && v) threads = std::atoi(argv[++i]);
    else if (a == "--dataset" && v) dataset = argv[++i];
    else if (a == "--max-peak-mb" && v) max_peak_mb = std::atof(argv[++i]);
    else if (a == "--max-growth-mb" && v) max_growth_mb = std::atof(argv[++i]);
    else {
      std::fprintf(stderr, "usage: %s [--frames N] [--threads N] [--dataset DIR] [--max-peak-mb MB] [--max-growth-mb MB]\n", argv[0]);
      return 2;
    }
  }
  if (frames < 1) frames = 1;

  std::string temp_dir;
  if (dataset.empty()) {
    char pattern[] = "/tmp/tunnelmap-rss-XXXXXX";
    if (!mkdtemp(pattern)) {
      std::perror("mkdtemp");
      return 2;
    }
    temp_dir = pattern;
    dataset = temp_dir + "/lab";
    if (!write_dataset_in_child(dataset)) {
      fs::remove_all(temp_dir);
      return 2;
    }
  }
  int rc = 0;
  try {
    const double start_rss = status_mb("VmRSS");
    CyclingSource source(open_input(dataset, ReadOptions()), frames);
    Parameters params;
    params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
    Pipeline pipeline(params);
    if (source.dataset()) pipeline.set_world_up(source.dataset()->up);
    TunnelContext context;
    SequenceOptions opt;
    opt.threads = threads;
    SequenceRunner runner(pipeline, &context, opt);
    std::size_t detected = 0, errors = 0;
    double rss_100 = -1.0, rss_last = -1.0;  // while running, at frame 100 and the last frame
    const auto t0 = std::chrono::steady_clock::now();
    std::printf("frames %zu, threads %d, input %s; RSS at start %.1f MB\n", frames, threads,
                dataset.c_str(), start_rss);
    const SequenceStats stats = runner.run(source, [&](SequenceFrame& f) {
      if (!f.ok()) {
        ++errors;
        std::fprintf(stderr, "frame %zu: %s\n", f.index, f.error_message.c_str());
      } else if (f.result.map.detected) {
        ++detected;
      }
      const std::size_t done = f.index + 1;
      if (done == 100 || done == 500 || done == 1000 || done == frames || done % 1000 == 0) {
        const double rss = status_mb("VmRSS");
        if (done == std::min<std::size_t>(100, frames)) rss_100 = rss;
        rss_last = rss;
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf("frame %5zu: RSS %.1f MB, peak %.1f MB, %.1f s, %.1f fps\n", done, rss,
                    status_mb("VmHWM"), s, done / s);
        std::fflush(stdout);
      }
      return true;
    });
    const double peak = status_mb("VmHWM");
    std::printf("%zu/%zu frames detected, %zu errors; peak RSS %.1f MB (limit %.0f), growth "
                "frame 100 -> last frame %.1f MB (limit %.0f)\n",
                detected, stats.delivered, errors, peak, max_peak_mb, rss_last - rss_100, max_growth_mb);
    if (stats.delivered != frames || errors > 0) rc = 1;
    if (peak > max_peak_mb) {
      std::printf("FAIL: peak RSS %.1f MB > %.0f MB\n", peak, max_peak_mb);
      rc = 1;
    }
    if (rss_100 >= 0 && rss_last - rss_100 > max_growth_mb) {
      std::printf("FAIL: RSS grew by %.1f MB > %.0f MB\n", rss_last - rss_100, max_growth_mb);
      rc = 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tunnelmap_sequence_rss: %s\n", e.what());
    rc = 2;
  }
  if (!temp_dir.empty()) fs::remove_all(temp_dir);
  return rc;
}
