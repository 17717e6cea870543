#pragma once
// Live view plumbing: a thread reads every frame from a LiveDevice and keeps only the newest, so
// a slower consumer (pipeline + rendering) always processes the latest frame and stale ones are
// dropped instead of queueing up. Counts received / dropped frames for the fps display.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "sensors/openni/live_device.h"

namespace tunnelmap::openni2 {

struct GrabbedFrame {
  DepthFrame frame;
  std::uint64_t sequence = 0;                     // 1, 2, ... in arrival order (gaps = dropped)
  std::chrono::steady_clock::time_point arrived;  // when the frame reached the host: latency origin
};

struct GrabberStats {
  std::uint64_t received = 0, taken = 0, dropped = 0;
};

class LatestFrameGrabber {
 public:
  explicit LatestFrameGrabber(std::unique_ptr<LiveDevice> device);  // starts streaming
  ~LatestFrameGrabber();                                            // stops and joins

  // The newest frame not taken yet; waits up to `timeout_ms`. nullopt on timeout. Rethrows the
  // device's error (e.g. "device disconnected after N frames") once no frame is left.
  std::optional<GrabbedFrame> take_latest(int timeout_ms);
  GrabberStats stats() const;
  // Parks the reader, stops the streams, runs `fn`, then streams again (e.g. to finish an
  // OniRecording safely, see oni_recording.h). Rethrows what `fn` throws, after restarting.
  void with_streams_paused(const std::function<void()>& fn);
  LiveDevice& device() { return *device_; }  // e.g. to attach an OniRecording

 private:
  void run();
  std::unique_ptr<LiveDevice> device_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::optional<GrabbedFrame> latest_;
  std::string error_;
  std::string error_file_;
  GrabberStats stats_;
  bool quit_ = false;
  bool pause_ = false, parked_ = false;  // with_streams_paused: asked, and the reader is waiting
  std::thread thread_;
};

}  // namespace tunnelmap::openni2
