// Whole-sequence throughput: a 30-frame simulated dataset read from disk (PNG decoding
// included), detected through the run engine with the context applied in order, on 1
// thread and on every core. Counter "fps" = frames per second of wall time; "cores_used" =
// process CPU time / wall time (below the thread count when other processes share the cores,
// then fps says nothing about scaling).
//   tunnelmap_bench --benchmark_filter=Sequence
// The datasets are written once to $TMPDIR/tunnelmap-sequence-bench/PRESET (reused afterwards).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "core/engine/run_engine.h"
#include "core/io/frame_source.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"

namespace tunnelmap::bench {
namespace {

double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string sequence_dataset(const std::string& preset) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "tunnelmap-sequence-bench" / preset;
  if (!fs::exists(dir / "dataset.json")) {
    SimConfig config = SimConfig::from_preset(preset);
    config.frames = 30;
    config.seed = preset == "lab" ? 5 : 6;
    write_sim_dataset(dir.string(), config);
  }
  return dir.string();
}

void BM_Sequence(benchmark::State& state, const std::string& preset) {
  const int threads = static_cast<int>(state.range(0));
  const std::unique_ptr<FrameSource> source = open_input(sequence_dataset(preset), ReadOptions());
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/" + preset + ".json");
  RunSettings settings;
  settings.params = params;
  settings.threads = threads;
  std::size_t frames = 0, detected = 0;
  const double cpu0 = process_cpu_s();
  const auto wall0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    RunEngine engine(settings, source.get());  // a fresh context per pass
    engine.run(*source, [&](SequenceFrame& f) {
      ++frames;
      detected += f.ok() && f.result.map.detected;
      return true;
    });
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  state.counters["cores_used"] = wall > 0 ? (process_cpu_s() - cpu0) / wall : 0.0;
  state.counters["fps"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
  state.counters["detected_pct"] = frames ? 100.0 * detected / frames : 0.0;
  state.counters["threads"] = resolve_thread_count(threads);
}

void sequence_args(benchmark::internal::Benchmark* b) {
  b->Arg(1);
  const int all = resolve_thread_count(0);
  if (all > 1) b->Arg(all);
  b->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
}

BENCHMARK_CAPTURE(BM_Sequence, lab, std::string("lab"))->Apply(sequence_args);
BENCHMARK_CAPTURE(BM_Sequence, field, std::string("field"))->Apply(sequence_args);

}  // namespace
}  // namespace tunnelmap::bench
