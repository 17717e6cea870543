// Reading a robot recording: depth frames per second out of a zstd-compressed MCAP (32FC1
// VGA depth, rgb8 colour, camera info and odometry at each frame, as a ROS 2 camera driver
// records them), through RecordingFrames: chunk decompression, CDR decoding, depth
// conversion, colour pairing and the pose. Counter "frames_per_s" (target: 300 on one core).
//   tunnelmap_bench --benchmark_filter=RecordingFrames
// The recording is written once to $TMPDIR/tunnelmap-recording-bench (reused afterwards).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/io/dataset.h"
#include "core/recordings/recording.h"
#include "core/recordings/recording_frames.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/posed_bag.h"

namespace tunnelmap::bench {
namespace {

std::string zstd_mcap() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "tunnelmap-recording-bench";
  const fs::path bag = dir / "posed_zstd.mcap";
  if (!fs::exists(bag)) {
    SimConfig c = SimConfig::from_preset("lab");
    c.frames = 30;
    write_sim_dataset((dir / "sim").string(), c);
    const Dataset ds = read_dataset((dir / "sim").string());
    testing::McapWriter w(bag.string(), {});
    testing::write_posed_bag(ds, [&](const std::string& topic, const std::string& type, std::int64_t t,
                                     const std::vector<std::uint8_t>& cdr) {
      w.write(topic, type, static_cast<std::uint64_t>(t), cdr);
    });
    w.close();
  }
  return bag.string();
}

void BM_RecordingFramesZstdMcap(benchmark::State& state) {
  const auto rec = recordings::open_recording(zstd_mcap());
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

BENCHMARK(BM_RecordingFramesZstdMcap)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace tunnelmap::bench
