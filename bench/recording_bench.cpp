// Depth frames per second read from robot recordings of a simulated posed sequence (VGA depth
// and camera info as a ROS driver records them, the camera pose from odometry or TF), through
// RecordingFrames: chunk decompression, CDR or ROS 1 decoding, depth conversion, colour
// pairing and the pose. Counter "frames_per_s" (target: 300 depth frames per second on one
// core).
//   BM_RecordingFramesZstdMcap  zstd MCAP, 32FC1 depth with rgb8 colour (paired and decoded)
//   BM_RecordingDepthZstdMcap   zstd MCAP, 32FC1 depth only
//   BM_RecordingDepthLz4Ros1    lz4 ROS 1 bag (the real writer), 16UC1 depth only, TF poses
//   tunnelmap_bench --benchmark_filter=Recording
// The recordings are written once to $TMPDIR/tunnelmap-recording-bench (reused afterwards).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <functional>

#include "core/io/dataset.h"
#include "core/recordings/recording.h"
#include "core/recordings/recording_frames.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/posed_bag.h"
#ifdef TUNNELMAP_BENCH_ROS1_WRITER
#include "tests/support_ros1/posed_ros1_bag.h"
#endif

namespace tunnelmap::bench {
namespace {

namespace fs = std::filesystem;

const fs::path& bench_dir() {
  static const fs::path dir = fs::temp_directory_path() / "tunnelmap-recording-bench";
  return dir;
}

const Dataset& sequence() {
  static const Dataset ds = [] {
    const fs::path sim = bench_dir() / "sim";
    if (!fs::exists(sim / "dataset.json")) {
      SimConfig c = SimConfig::from_preset("lab");
      c.frames = 30;
      write_sim_dataset(sim.string(), c);
    }
    return read_dataset(sim.string());
  }();
  return ds;
}

// The recording at `name`, written by `write` the first time.
std::string recording(const std::string& name, const std::function<void(const std::string&)>& write) {
  const fs::path bag = bench_dir() / name;
  if (!fs::exists(bag)) write(bag.string());
  return bag.string();
}

std::string zstd_mcap(bool colour) {
  return recording(colour ? "posed_zstd.mcap" : "depth_zstd.mcap", [colour](const std::string& path) {
    testing::McapWriter w(path, {});
    testing::write_posed_bag(sequence(), [&](const std::string& topic, const std::string& type, std::int64_t t,
                                             const std::vector<std::uint8_t>& cdr) {
      if (colour || topic != testing::kBagColorTopic) w.write(topic, type, static_cast<std::uint64_t>(t), cdr);
    });
    w.close();
  });
}

void read_frames(benchmark::State& state, const std::string& path) {
  const auto rec = recordings::open_recording(path);
  const recordings::RecordingFrames frames(*rec, recordings::RecordingOptions{}, ReadOptions{});
  std::size_t n = 0;
  for (auto _ : state) {
    frames.for_each_frame([&](DepthFrame& f) {
      benchmark::DoNotOptimize(f.depth.data());
      ++n;
      return true;
    });
  }
  state.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
}

void BM_RecordingFramesZstdMcap(benchmark::State& state) { read_frames(state, zstd_mcap(true)); }
void BM_RecordingDepthZstdMcap(benchmark::State& state) { read_frames(state, zstd_mcap(false)); }
BENCHMARK(BM_RecordingFramesZstdMcap)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RecordingDepthZstdMcap)->Unit(benchmark::kMillisecond)->UseRealTime();

#ifdef TUNNELMAP_BENCH_ROS1_WRITER
void BM_RecordingDepthLz4Ros1(benchmark::State& state) {
  read_frames(state, recording("depth_lz4.bag", [](const std::string& path) {
                testing::Ros1PosedBagOptions o;
                o.colour = false;
                testing::write_posed_ros1_bag(sequence(), path, o);
              }));
}
BENCHMARK(BM_RecordingDepthLz4Ros1)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

}  // namespace
}  // namespace tunnelmap::bench
