#pragma once
// Raw per-run wall times of TunnelMap's plane extraction and the in-process peers (OpenCV,
// PCL) on the bench frames, for pooling with peers timed by their own harness in the same
// session (scripts/bench-cape.sh: CAPE). Google Benchmark's repetitions restart each benchmark
// with fresh buffers; here, as in CAPE's harness, buffers persist and warm-up runs are dropped.
#include <string>

namespace tunnelmap::bench {

// Prints "RAW|frame|method|planes|ms ms ..." per frame and method (tunnelmap, tunnelmap-pixel-grid,
// tunnelmap-detection, opencv, pcl):
// `reps` timed runs after `warmup` untimed ones; only the methods named in `methods`
// (comma-separated).
int print_timed_runs(int reps, int warmup, const std::string& methods);

}  // namespace tunnelmap::bench
