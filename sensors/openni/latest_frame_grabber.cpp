#include "sensors/openni/latest_frame_grabber.h"

#include <exception>

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
  cv_.notify_all();  // a parked reader wakes up to quit
  thread_.join();
  device_->stop();
}

void LatestFrameGrabber::run() {
  std::uint64_t sequence = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (pause_) {
        parked_ = true;
        cv_.notify_all();
        cv_.wait(lock, [&] { return !pause_ || quit_; });
        parked_ = false;
      }
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

void LatestFrameGrabber::with_streams_paused(const std::function<void()>& fn) {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    pause_ = true;
    // The reader parks within one read (200 ms), or has already stopped on an error.
    cv_.wait(lock, [&] { return parked_ || !error_.empty(); });
  }
  device_->stop();
  std::exception_ptr failure;
  try {
    fn();
  } catch (...) {
    failure = std::current_exception();
  }
  try {
    device_->start();
  } catch (...) {  // the reader's next read retries and reports it
    if (!failure) failure = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pause_ = false;
  }
  cv_.notify_all();
  if (failure) std::rethrow_exception(failure);
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
