// Re-meshing after one more frame against meshing the whole volume, on a simulated field
// girder walked over 10 m (50 frames, one every 0.2 m, exact poses, 8 mm voxels, 2 threads;
// written once to $TMPDIR/tunnelmap-remesh-bench):
//   tunnelmap_bench --benchmark_filter=Remesh
// BM_RemeshAfterOneFrame: IncrementalMesher::update after the last frame is integrated again
// (timed: the update only); BM_RemeshFull: extract_mesh of the same volume; BM_RemeshMerge:
// IncrementalMesher::mesh, the kept chunks joined into one mesh. Counters: chunks re-extracted,
// chunks in all, blocks, vertices.
#include <benchmark/benchmark.h>

#include "bench/field_walk.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/kinematics/frame_pose.h"
#include "mesh/sparse_mesher.h"
#include "mesh/tsdf_mesher.h"

namespace tunnelmap::bench {
namespace {

struct FusedWalk {
  std::unique_ptr<SparseTsdfVolume> volume;
  DepthFrame last;
  Eigen::Isometry3d last_pose = Eigen::Isometry3d::Identity();
  int min_weight = 0;
};

// A fresh volume per benchmark (BM_RemeshAfterOneFrame integrates into its own).
FusedWalk fused_walk() {
  const Dataset ds = field_walk_dataset({"tunnelmap-remesh-bench", 50, 50, 10.3, {4.0, 8.0}});
  const FusionOptions o;
  TsdfOptions t = tsdf_options(o);
  t.threads = 2;
  FusedWalk f;
  f.volume = std::make_unique<SparseTsdfVolume>(o.voxel_m, t);
  f.min_weight = o.min_weight;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) f.volume->integrate(ds.load_frame(i), *resolve_frame_pose(ds, i).pose);
  f.last = ds.load_frame(ds.frames.size() / 2);  // a frame in the middle of the walk
  f.last_pose = *resolve_frame_pose(ds, ds.frames.size() / 2).pose;
  return f;
}

void BM_RemeshAfterOneFrame(benchmark::State& state) {
  FusedWalk w = fused_walk();
  IncrementalMesher mesher(w.min_weight);
  mesher.update(*w.volume);
  std::size_t chunks = 0;
  for (auto _ : state) {
    state.PauseTiming();
    w.volume->integrate(w.last, w.last_pose);
    state.ResumeTiming();
    chunks = mesher.update(*w.volume);
  }
  state.counters["chunks"] = double(chunks);
  state.counters["all_chunks"] = double(occupied_chunks(*w.volume).size());
  state.counters["blocks"] = double(w.volume->block_count());
}

void BM_RemeshFull(benchmark::State& state) {
  FusedWalk w = fused_walk();
  std::size_t vertices = 0;
  for (auto _ : state) vertices = extract_mesh(*w.volume, w.min_weight).vertices.size();
  state.counters["all_chunks"] = double(occupied_chunks(*w.volume).size());
  state.counters["vertices"] = double(vertices);
}

void BM_RemeshMerge(benchmark::State& state) {
  FusedWalk w = fused_walk();
  IncrementalMesher mesher(w.min_weight);
  mesher.update(*w.volume);
  std::size_t vertices = 0;
  for (auto _ : state) vertices = mesher.mesh().vertices.size();
  state.counters["vertices"] = double(vertices);
}

BENCHMARK(BM_RemeshAfterOneFrame)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_RemeshFull)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_RemeshMerge)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace tunnelmap::bench
