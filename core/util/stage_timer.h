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
  ~StageTimer() {
    const auto end = std::chrono::steady_clock::now();
    out_[name_] += std::chrono::duration<double, std::milli>(end - start_).count();
  }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  StageTimings& out_;
  std::string name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace tunnelmap
