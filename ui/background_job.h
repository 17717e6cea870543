#pragma once
// The window's one background job (Process whole sequence, Map tunnel or Fuse sequence): at
// most one runs, a new input or the live camera cancels it, and the window waits for it before
// it closes.
#include <QFuture>
#include <atomic>
#include <functional>

namespace tunnelmap::ui {

class BackgroundJob {
 public:
  bool running() const { return running_; }
  // Runs `work` on a worker thread with the cancel flag cleared; false, and nothing started,
  // while another job runs. The job calls finished() on the GUI thread when it is done.
  bool start(std::function<void()> work);
  void finished() { running_ = false; }
  void cancel() { cancel_.store(true); }
  bool cancelled() const { return cancel_.load(); }
  const std::atomic<bool>& cancel_flag() const { return cancel_; }
  void wait() { future_.waitForFinished(); }

 private:
  bool running_ = false;
  std::atomic<bool> cancel_{false};
  QFuture<void> future_;
};

}  // namespace tunnelmap::ui
