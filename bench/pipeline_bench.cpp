// Stage-by-stage timing of the PG&C pipeline on VGA frames, one thread, Release.
// Run: ./build/bench/tunnelmap_bench --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include "bench/bench_frames.h"
#include "core/pipeline/pipeline.h"

using namespace tunnelmap;
using tunnelmap::bench::bench_frames;

namespace {

void BM_Cloud(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  for (auto _ : state) build_cloud(f, cloud_options(p), cloud);
  state.SetLabel(bench_frames()[state.range(0)].name);
}

void BM_Normals(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(f, cloud_options(p), cloud);
  for (auto _ : state) estimate_normals(normal_options(p), cloud);
  state.SetLabel(bench_frames()[state.range(0)].name);
}

void BM_Grow(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(f, cloud_options(p), cloud);
  estimate_normals(normal_options(p), cloud);
  GrowOptions g = grow_options(p);
  g.compute_contours = false;
  std::size_t planes = 0;
  for (auto _ : state) planes = extract_planes(cloud, g).planes.size();
  state.counters["planes"] = static_cast<double>(planes);
  state.SetLabel(bench_frames()[state.range(0)].name);
}

// The paper's "plane extraction": cloud + normals + PG&C + areas + contours.
void BM_PlaneExtraction(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  std::size_t planes = 0;
  for (auto _ : state) {
    build_cloud(f, cloud_options(p), cloud);
    estimate_normals(normal_options(p), cloud);
    planes = extract_planes(cloud, grow_options(p)).planes.size();
  }
  state.counters["planes"] = static_cast<double>(planes);
  state.SetLabel(bench_frames()[state.range(0)].name);
}

// Full detection: plane extraction + tunnel template fit.
void BM_Detection(benchmark::State& state) {
  const auto& nf = bench_frames()[state.range(0)];
  Pipeline pipeline;
  FrameResult result;
  for (auto _ : state) pipeline.run(nf.frame, result, nullptr);
  state.counters["detected"] = result.map.detected ? 1 : 0;
  state.SetLabel(nf.name);
}

void frame_args(benchmark::internal::Benchmark* b) {
  for (std::size_t i = 0; i < bench_frames().size(); ++i) b->Arg(static_cast<int>(i));
  b->Unit(benchmark::kMillisecond)->ComputeStatistics("median", [](const std::vector<double>& v) {
    std::vector<double> s = v;
    std::sort(s.begin(), s.end());
    return s[s.size() / 2];
  });
}

}  // namespace

BENCHMARK(BM_Cloud)->Apply(frame_args);
BENCHMARK(BM_Normals)->Apply(frame_args);
BENCHMARK(BM_Grow)->Apply(frame_args);
BENCHMARK(BM_PlaneExtraction)->Apply(frame_args);
BENCHMARK(BM_Detection)->Apply(frame_args);
BENCHMARK_MAIN();
