// Benchmark entry point: everything on one thread so the per-frame figures compare single-core
// work (OpenCV's own pool off; scripts/bench.sh also sets OMP_NUM_THREADS=1 for PCL/OpenMP,
// which libgomp reads before main runs).
// `tunnelmap_bench --export-frames DIR` only writes the bench frames as depth PNGs (for peers
// timed outside this binary, scripts/bench-cape.sh) and exits; `--timed-runs N` only prints N
// raw wall times per frame and method (bench/timed_runs.h) and exits; `--timed-runs N tunnelmap`
// times only the named methods (comma-separated: tunnelmap, tunnelmap-pixel-grid,
// tunnelmap-detection, opencv, pcl), e.g. for A/B runs.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <opencv2/core.hpp>

#include "bench/frame_export.h"
#include "bench/timed_runs.h"

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--export-frames") == 0)
    return tunnelmap::bench::export_bench_frames(argv[2]) ? 0 : 3;
  cv::setNumThreads(1);
  if ((argc == 3 || argc == 4) && std::strcmp(argv[1], "--timed-runs") == 0) {
    const int reps = std::atoi(argv[2]);
    if (reps < 1) return 2;
    const char* all = "tunnelmap,tunnelmap-pixel-grid,tunnelmap-detection,opencv,pcl";
    return tunnelmap::bench::print_timed_runs(reps, 3, argc == 4 ? argv[3] : all);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("opencv_threads", std::to_string(cv::getNumThreads()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
