#include "sensors/openni/latest_frame_grabber.h"

#include "core/util/error.h"

namespace tunnelmap::openni2 {

LatestFrameGrabber::LatestFrameGrabber(std::unique_ptr<LiveDevice> device) : device_(std::move(device)) {
  device_->start();
  thread_ = std::thread([this] { run(); });
}

LatestFrameGrabber::~LatestFrameGrabber() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  thread_.join();
  device_->stop();
}

void LatestFrameGrabber::run() {
  std::uint64_t sequence = 0;
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (quit_) return;
    }
    try {
      DepthFrame f = device_->read(200);
      std::lock_guard<std::mutex> lock(mutex_);
      if (latest_) ++stats_.dropped;  // never taken: replaced by a newer one
      latest_ = GrabbedFrame{std::move(f), ++sequence, std::chrono::steady_clock::now()};
      ++stats_.received;
      cv_.notify_all();
    } catch (const InputError& e) {
      if (!device_->disconnected() && e.problem().rfind("no depth frame within", 0) == 0) continue;  // keep waiting
      std::lock_guard<std::mutex> lock(mutex_);
      error_file_ = e.file();
      error_ = e.problem();
      cv_.notify_all();
      return;
    }
  }
}

std::optional<GrabbedFrame> LatestFrameGrabber::take_latest(int timeout_ms) {
  std::unique_lock<std::mutex> lock(mutex_);
  cv_.wait_for(lock, std::chrono::milliseconds(timeout_ms), [&] { return latest_.has_value() || !error_.empty(); });
  if (latest_) {
    std::optional<GrabbedFrame> out = std::move(latest_);
    latest_.reset();
    ++stats_.taken;
    return out;
  }
  if (!error_.empty()) throw InputError(error_file_, error_);
  return std::nullopt;
}

GrabberStats LatestFrameGrabber::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

}  // namespace tunnelmap::openni2
