// Benchmark entry point: everything on one thread so the per-frame figures compare single-core
// work (OpenCV's own pool off; scripts/bench.sh also sets OMP_NUM_THREADS=1 for PCL/OpenMP,
// which libgomp reads before main runs).
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>

int main(int argc, char** argv) {
  cv::setNumThreads(1);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("opencv_threads", std::to_string(cv::getNumThreads()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
