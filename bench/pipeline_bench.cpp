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
  GrowOptions g = grow_options(p);
  if (needs_point_normals(g)) estimate_normals(normal_options(p), cloud);
  g.compute_contours = false;
  PlaneSegments planes;
  FrameScratch scratch;
  for (auto _ : state) extract_planes(cloud, g, planes, scratch.planes);
  state.counters["planes"] = static_cast<double>(planes.planes.size());
  state.SetLabel(bench_frames()[state.range(0)].name);
}

// The growing orders measured: the default (8 x 8 pixel cells), and the pixel grid
// (grow.cell_px = 0) on every other pixel or on every pixel (the paper's growing order).
enum class Order { Default, PixelGrid, EveryPixel };

// Default parameters with the growing order; edge_on_pass 0 or 1 overrides
// grow.edge_on_pass, -1 keeps the default (on).
Parameters params_for(Order order, int edge_on_pass = -1) {
  Parameters p;
  if (order != Order::Default) p.set("grow.cell_px", 0);
  if (order == Order::EveryPixel) p.set("grow.grid_step", 1);
  if (edge_on_pass >= 0) p.set("grow.edge_on_pass", edge_on_pass);
  return p;
}

// The paper's "plane extraction": cloud + normals (for the pixel grid; cells need none) +
// PG&C + areas + contours.
void plane_extraction(benchmark::State& state, Order order, int edge_on_pass = -1) {
  const DepthFrame& f = bench_frames()[state.range(0)].frame;
  const Parameters p = params_for(order, edge_on_pass);
  const CloudOptions co = cloud_options(p);
  const NormalOptions no = normal_options(p);
  const GrowOptions go = grow_options(p);
  const bool normals = needs_point_normals(go);
  OrganizedCloud cloud;
  PlaneSegments planes;
  FrameScratch scratch;
  for (auto _ : state) {
    build_cloud(f, co, cloud, scratch.cloud);
    if (normals) estimate_normals(no, cloud, scratch.normals);
    extract_planes(cloud, go, planes, scratch.planes);
  }
  tunnelmap::bench::set_plane_counters(state, bench_frames()[state.range(0)], planes);
  state.SetLabel(bench_frames()[state.range(0)].name);
}
// The default: growing over 8 x 8 pixel cells, pixels assigned one by one at plane borders.
void BM_PlaneExtraction(benchmark::State& state) { plane_extraction(state, Order::Default); }
// The default without its edge-on pass (what it costs, and what it finds: docs/recall.md).
void BM_PlaneExtractionNoEdgeOnPass(benchmark::State& state) { plane_extraction(state, Order::Default, 0); }
// The pixel grid: grow on every other pixel, assign the rest by eq. 2 (grow.cell_px = 0).
void BM_PlaneExtractionPixelGrid(benchmark::State& state) { plane_extraction(state, Order::PixelGrid); }
// The paper's growing over every pixel (grow.cell_px = 0, grow.grid_step = 1).
void BM_PlaneExtractionEveryPixel(benchmark::State& state) { plane_extraction(state, Order::EveryPixel); }

// Full detection: plane extraction + tunnel template fit.
void detection(benchmark::State& state, Order order) {
  const auto& nf = bench_frames()[state.range(0)];
  Pipeline pipeline(params_for(order));
  FrameResult result;
  for (auto _ : state) pipeline.run(nf.frame, result, nullptr);
  state.counters["detected"] = result.map.detected ? 1 : 0;
  state.counters["planes"] = static_cast<double>(result.planes.planes.size());
  state.SetLabel(nf.name);
}
void BM_Detection(benchmark::State& state) { detection(state, Order::Default); }
void BM_DetectionPixelGrid(benchmark::State& state) { detection(state, Order::PixelGrid); }
void BM_DetectionEveryPixel(benchmark::State& state) { detection(state, Order::EveryPixel); }

}  // namespace

BENCHMARK(BM_Cloud)->Apply(per_frame);
BENCHMARK(BM_Normals)->Apply(per_frame);
BENCHMARK(BM_Grow)->Apply(per_frame);
BENCHMARK(BM_PlaneExtraction)->Apply(per_frame);
BENCHMARK(BM_PlaneExtractionNoEdgeOnPass)->Apply(per_frame);
BENCHMARK(BM_PlaneExtractionPixelGrid)->Apply(per_frame);
BENCHMARK(BM_PlaneExtractionEveryPixel)->Apply(per_frame);
BENCHMARK(BM_Detection)->Apply(per_frame);
BENCHMARK(BM_DetectionPixelGrid)->Apply(per_frame);
BENCHMARK(BM_DetectionEveryPixel)->Apply(per_frame);
