#pragma once
// Every benchmark runs once per bench frame (argument = index into bench_frames()), in ms.
#include <benchmark/benchmark.h>

#include "bench/bench_frames.h"

namespace tunnelmap::bench {

inline void per_frame(benchmark::internal::Benchmark* b) {
  for (std::size_t i = 0; i < bench_frames().size(); ++i) b->Arg(static_cast<int>(i));
  b->Unit(benchmark::kMillisecond);
}

}  // namespace tunnelmap::bench
