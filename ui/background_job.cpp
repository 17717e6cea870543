#include "ui/background_job.h"

#include <QtConcurrent/QtConcurrentRun>

namespace tunnelmap::ui {

bool BackgroundJob::start(std::function<void()> work) {
  if (running_) return false;
  running_ = true;
  cancel_.store(false);
  future_ = QtConcurrent::run(std::move(work));
  return true;
}

}  // namespace tunnelmap::ui
