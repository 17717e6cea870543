#pragma once
// Run-time choice between a kernel's AVX2 and SSE variants: AVX2 when the CPU has it (so the
// package runs on any x86-64), unless tests force SSE to compare both. One per kernel family.
#include <atomic>

namespace tunnelmap {

class Avx2Dispatch {
 public:
  bool use_avx2() const {
    static const bool cpu_has_avx2 = __builtin_cpu_supports("avx2");
    return cpu_has_avx2 && !sse_only_.load(std::memory_order_relaxed);
  }
  void force_sse(bool on) { sse_only_.store(on, std::memory_order_relaxed); }

 private:
  std::atomic<bool> sse_only_{false};
};

}  // namespace tunnelmap
