// Soak test (long streams): 5,000 frames from the simulated OpenNI2 camera through the
// streaming path `detect --device` uses (DeviceFrameSource -> LiveDevice -> OpenNI2 -> the
// project's driver), the full Pipeline with a TunnelContext on every frame. After warm-up,
// resident memory may grow by less than 5 % and no file descriptor may stay open.
// The camera runs with fps=0 (paced by the reader, sim_driver_protocol.h): no frame is lost, so
// every frame index arrives, in order, and the run takes as long as the pipeline needs.
// TUNNELMAP_SOAK_FRAMES=N runs a shorter soak (local checks; the sanitizer build).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/params/parameters.h"
#include "core/pipeline/pipeline.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "sensors/openni/device_frame_source.h"
#include "sensors/openni/openni_context.h"
#include "tests/soak/process_stats.h"

using namespace tunnelmap;

// ASan's quarantine and shadow memory grow the resident set by design: under the sanitizer build
// the memory bound is not checked (LeakSanitizer checks for leaks instead).
#if defined(__SANITIZE_ADDRESS__)
#define TUNNELMAP_SOAK_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TUNNELMAP_SOAK_ASAN 1
#endif
#endif
#ifndef TUNNELMAP_SOAK_ASAN
#define TUNNELMAP_SOAK_ASAN 0
#endif

namespace {
constexpr int kCycle = 10;  // simulator frames rendered before streaming starts: cheap start-up
const std::string kUri = "tunnelmap-sim://lab?frames=" + std::to_string(kCycle) + "&fps=0";

int soak_frames() {
  const char* v = std::getenv("TUNNELMAP_SOAK_FRAMES");
  const int n = v != nullptr ? std::atoi(v) : 5000;
  return std::max(n, 20);
}

int sim_index(const DepthFrame& f) { return static_cast<int>(std::lround(f.timestamp_s * 30.0)); }

// The camera's depth (mm, rounded) equals the simulator's frame: the stream is not stale or torn.
bool same_depth(const DepthFrame& got, const DepthFrame& sim) {
  if (got.width != sim.width || got.height != sim.height) return false;
  for (std::size_t i = 0; i < got.depth.size(); ++i)
    if (got.depth[i] != static_cast<float>(std::lround(sim.depth[i]))) return false;
  return true;
}

double mb(long kb) { return kb / 1024.0; }
}  // namespace

TEST(Soak, LiveStreamThroughThePipelineKeepsMemoryAndFileDescriptorsFlat) {
  const int frames = soak_frames();
  const int warmup = std::min(500, frames / 10);
  openni2::ensure_initialized();
  const int fds_before_device = soak::open_fds();

  SimConfig config = SimConfig::from_preset("lab");
  config.frames = kCycle;
  const TunnelSimulator sim(config);
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  const Pipeline pipeline(params);  // world up +Z through the camera's poses

  long rss_warm = 0, rss_end = 0;
  int fds_warm = 0, fds_end = 0, detected = 0, out_of_order = 0, wrong_pose = 0, wrong_depth = 0;
  std::vector<long> rss_samples;  // every 1000 frames: a trend, not two points
  std::chrono::steady_clock::time_point t_warm;
  const auto t_start = std::chrono::steady_clock::now();
  {
    openni2::DeviceFrameSource source(kUri, static_cast<std::size_t>(frames), ReadOptions());
    TunnelContext context;  // as `detect` keeps one over a sequence (Pipeline::run accepts into it)
    FrameResult result;
    for (int i = 0; i < frames; ++i) {
      const DepthFrame f = source.load(static_cast<std::size_t>(i));
      out_of_order += sim_index(f) != i;  // lossless: frame i is the camera's i-th frame
      wrong_pose += !f.pose || !f.pose->isApprox(sim.pose(i % kCycle), 1e-12);
      if (i % 1000 == 999) wrong_depth += !same_depth(f, sim.render(i % kCycle).frame);
      pipeline.run(f, result, &context);
      detected += result.map.detected;
      if ((i + 1) % 1000 == 0) rss_samples.push_back(soak::resident_kb());
      if (i + 1 == warmup) {
        rss_warm = soak::resident_kb();
        fds_warm = soak::open_fds();
        t_warm = std::chrono::steady_clock::now();
      }
    }
    rss_end = soak::resident_kb();
    fds_end = soak::open_fds();
    EXPECT_EQ(source.device().frames_read(), frames);
  }
  const auto t_end = std::chrono::steady_clock::now();
  const int fds_after_device = soak::open_fds();
  // Reconnecting (the GUI's live view does on every unplug) must not leak either.
  constexpr int kReconnects = 10;
  for (int r = 0; r < kReconnects; ++r) {
    openni2::DeviceFrameSource again(kUri, 3, ReadOptions());
    for (std::size_t i = 0; i < again.size(); ++i) ASSERT_FALSE(again.load(i).empty());
  }
  const int fds_after_reconnects = soak::open_fds();

  const double growth = 100.0 * (rss_end - rss_warm) / rss_warm;
  const double wall_s = std::chrono::duration<double>(t_end - t_start).count();
  const double soak_s = std::chrono::duration<double>(t_end - t_warm).count();
  std::printf("[ soak ] %d frames through OpenNI2 (%s) + Pipeline in %.1f s (%.1f frames/s after warm-up); "
              "%d detected\n",
              frames, kUri.c_str(), wall_s, (frames - warmup) / soak_s, detected);
  std::printf("[ soak ] RSS %.1f MB after %d frames, %.1f MB at the end: %+.2f %%; open fds %d -> %d "
              "(%d before the device, %d after closing it, %d after %d reconnects)\n",
              mb(rss_warm), warmup, mb(rss_end), growth, fds_warm, fds_end, fds_before_device, fds_after_device,
              fds_after_reconnects, kReconnects);
  std::printf("[ soak ] RSS every 1000 frames (MB):");
  for (long kb : rss_samples) std::printf(" %.1f", mb(kb));
  std::printf("\n");

  EXPECT_EQ(out_of_order, 0) << "frames lost or out of order";
  EXPECT_EQ(wrong_pose, 0);
  EXPECT_EQ(wrong_depth, 0);
  EXPECT_EQ(detected, frames);
  ASSERT_GT(rss_warm, 0) << "cannot read /proc/self/status";
  if (TUNNELMAP_SOAK_ASAN)
    std::printf("[ soak ] AddressSanitizer build: RSS growth not checked\n");
  else
    EXPECT_LT(growth, 5.0);
  EXPECT_EQ(fds_end, fds_warm);
  EXPECT_EQ(fds_after_device, fds_before_device);
  EXPECT_EQ(fds_after_reconnects, fds_before_device);
}
