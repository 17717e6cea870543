#pragma once
// Each pipeline stage times itself into a StageTimings map (milliseconds, wall clock).
#include <chrono>
#include <map>
#include <string>

namespace tunnelmap {

using StageTimings = std::map<std::string, double>;

class StageTimer {
 public:
  StageTimer(StageTimings& out, std::string name)
      : out_(out), name_(std::move(name)), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { stop(); }
  // Records the time so far (once); the destructor then records nothing.
  void stop() {
    if (stopped_) return;
    stopped_ = true;
    const auto end = std::chrono::steady_clock::now();
    out_[name_] += std::chrono::duration<double, std::milli>(end - start_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  StageTimings& out_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
  bool stopped_ = false;
};

// Zeroes every entry but keeps the map's nodes, so timing a reused result allocates nothing.
inline void reset_timings(StageTimings& t) {
  for (auto& entry : t) entry.second = 0.0;
}

}  // namespace tunnelmap
