// Stage-by-stage timing of the PG&C pipeline on VGA frames, one thread, Release.
// Run: bash scripts/bench.sh (or build-*/bench/tunnelmap_bench --benchmark_filter=...).
#include <benchmark/benchmark.h>

#include "bench/bench_frames.h"
#include "bench/frame_args.h"
#include "bench/plane_quality.h"
#include "core/pipeline/pipeline.h"

using namespace tunnelmap;
using tunnelmap::bench::bench_frames;
using tunnelmap::bench::per_frame;

namespace {

void BM_Cloud(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  FrameScratch scratch;  // reused, as Pipeline::run does: the steady state
  for (auto _ : state) build_cloud(f, cloud_options(p), cloud, scratch.cloud);
  state.SetLabel(bench_frames()[state.range(0)].name);
}

void BM_Normals(benchmark::State& state) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p;
  OrganizedCloud cloud;
  build_cloud(f, cloud_options(p), cloud);
  FrameScratch scratch;
  for (auto _ : state) estimate_normals(normal_options(p), cloud, scratch.normals);
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
  PlaneSegments planes;
  FrameScratch scratch;
  for (auto _ : state) extract_planes(cloud, g, planes, scratch.planes);
  state.counters["planes"] = static_cast<double>(planes.planes.size());
  state.SetLabel(bench_frames()[state.range(0)].name);
}

// Default parameters with PG&C grown on every `grid_step`-th pixel (1 = the paper's growing;
// 0 = the table's default, the coarse-to-fine grid step 2); edge_on_pass 0 or 1 overrides
// grow.edge_on_pass, -1 keeps the default (on).
Parameters params_with_grid_step(int grid_step, int edge_on_pass = -1) {
  Parameters p;
  if (grid_step > 0) p.set("grow.grid_step", grid_step);
  if (edge_on_pass >= 0) p.set("grow.edge_on_pass", edge_on_pass);
  return p;
}

// The paper's "plane extraction": cloud + normals + PG&C + areas + contours.
void plane_extraction(benchmark::State& state, int grid_step, int edge_on_pass = -1) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p = params_with_grid_step(grid_step, edge_on_pass);
  const CloudOptions co = cloud_options(p);
  const NormalOptions no = normal_options(p);
  const GrowOptions go = grow_options(p);
  OrganizedCloud cloud;
  PlaneSegments planes;
  FrameScratch scratch;
  for (auto _ : state) {
    build_cloud(f, co, cloud, scratch.cloud);
    estimate_normals(no, cloud, scratch.normals);
    extract_planes(cloud, go, planes, scratch.planes);
  }
  tunnelmap::bench::set_plane_counters(state, bench_frames()[state.range(0)], planes);
  state.SetLabel(bench_frames()[state.range(0)].name);
}
// The default: the coarse-to-fine path (grow on every other pixel, assign the rest by eq. 2).
void BM_PlaneExtraction(benchmark::State& state) { plane_extraction(state, 0); }
// The default without its edge-on pass (what it costs, and what it finds: docs/recall.md).
void BM_PlaneExtractionNoEdgeOnPass(benchmark::State& state) { plane_extraction(state, 0, 0); }
// The paper's growing over every pixel (grow.grid_step = 1).
void BM_PlaneExtractionEveryPixel(benchmark::State& state) { plane_extraction(state, 1); }

// Full detection: plane extraction + tunnel template fit.
void detection(benchmark::State& state, int grid_step) {
  const auto& nf = bench_frames()[state.range(0)];
  Pipeline pipeline(params_with_grid_step(grid_step));
  FrameResult result;
  for (auto _ : state) pipeline.run(nf.frame, result, nullptr);
  state.counters["detected"] = result.map.detected ? 1 : 0;
  state.SetLabel(nf.name);
}
void BM_Detection(benchmark::State& state) { detection(state, 0); }
void BM_DetectionEveryPixel(benchmark::State& state) { detection(state, 1); }

// Full detection with the cell order (grow.cell_px = 8): what it costs next to CAPE's plane
// extraction alone (docs/performance.md).
void BM_DetectionCells(benchmark::State& state) {
  const auto& nf = bench_frames()[state.range(0)];
  Parameters p;
  p.set("grow.cell_px", 8);
  Pipeline pipeline(p);
  FrameResult result;
  for (auto _ : state) pipeline.run(nf.frame, result, nullptr);
  state.counters["detected"] = result.map.detected ? 1 : 0;
  state.counters["planes"] = static_cast<double>(result.planes.planes.size());
  state.SetLabel(nf.name);
}

}  // namespace

BENCHMARK(BM_Cloud)->Apply(per_frame);
BENCHMARK(BM_Normals)->Apply(per_frame);
BENCHMARK(BM_Grow)->Apply(per_frame);
BENCHMARK(BM_PlaneExtraction)->Apply(per_frame);
BENCHMARK(BM_PlaneExtractionNoEdgeOnPass)->Apply(per_frame);
BENCHMARK(BM_PlaneExtractionEveryPixel)->Apply(per_frame);
BENCHMARK(BM_Detection)->Apply(per_frame);
BENCHMARK(BM_DetectionEveryPixel)->Apply(per_frame);
BENCHMARK(BM_DetectionCells)->Apply(per_frame);
