// TSDF integration per VGA frame at 8 mm voxels on one thread (run under `taskset -c 0`):
// the sparse volume against the dense one over the data's box and against the same blocks on
// OpenVDB trees, in the same run.
//   taskset -c 0 tunnelmap_bench --benchmark_filter=Integrate
// "girder": a simulated field girder walked over 7 m (16 frames, 8 stops, diaphragms at 2.5 and
// 5 m; written once to $TMPDIR/tunnelmap-fusion-bench). "real": the real indoor frame
// real_rtabmap_lab (bench/bench_frames.h) fused 10 times from one pose with depth up to 4 m.
// Counters: ms_per_frame (wall), cpu_ms_per_frame (this thread's CPU time: the figure to read
// on a shared machine), blocks (sparse, OpenVDB: leaves), MiB of the volume.
#include <benchmark/benchmark.h>

#include <time.h>

#include <chrono>
#include <functional>

#include "bench/bench_frames.h"
#include "bench/field_walk.h"
#include "bench/openvdb_peer.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/tsdf_volume.h"
#include "core/io/dataset.h"
#include "core/kinematics/frame_pose.h"

namespace tunnelmap::bench {
namespace {

struct PosedFrames {
  std::vector<DepthFrame> frames;
  std::vector<Eigen::Isometry3d> poses;
  double max_depth_m = 2.5;
};

const PosedFrames& girder() {
  static const PosedFrames g = [] {
    const Dataset ds = field_walk_dataset({"tunnelmap-fusion-bench", 16, 8, 7.5, {2.5, 5.0}});
    PosedFrames p;
    for (std::size_t i = 0; i < ds.frames.size(); ++i) {
      p.frames.push_back(ds.load_frame(i));
      p.poses.push_back(*resolve_frame_pose(ds, i).pose);
    }
    return p;
  }();
  return g;
}

const PosedFrames& real_indoor() {
  static const PosedFrames r = [] {
    PosedFrames p;
    for (const NamedFrame& f : bench_frames())
      if (f.name == "real_rtabmap_lab")
        for (int k = 0; k < 10; ++k) {
          p.frames.push_back(f.frame);
          p.poses.push_back(Eigen::Isometry3d::Identity());
        }
    p.max_depth_m = 4.0;
    return p;
  }();
  return r;
}

const PosedFrames& input(int which) { return which == 0 ? girder() : real_indoor(); }

TsdfOptions one_thread(const PosedFrames& in, FusionOptions& o) {
  o.max_depth_m = in.max_depth_m;
  TsdfOptions t = tsdf_options(o);
  t.threads = 1;
  return t;
}

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Times `fuse` (which integrates every frame into a fresh volume) per frame.
void run(benchmark::State& state, const PosedFrames& in, const std::function<std::size_t()>& fuse) {
  double ms = 0, cpu_ms = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_ms();
    bytes = fuse();
    cpu_ms += thread_cpu_ms() - c0;
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  const double per_frame = double(state.iterations()) * double(in.frames.size());
  state.counters["ms_per_frame"] = ms / per_frame;
  state.counters["cpu_ms_per_frame"] = cpu_ms / per_frame;
  state.counters["MiB"] = double(bytes) / double(1 << 20);
}

void BM_IntegrateSparse(benchmark::State& state) {
  const PosedFrames& in = input(int(state.range(0)));
  FusionOptions o;
  const TsdfOptions t = one_thread(in, o);
  std::size_t blocks = 0;
  run(state, in, [&] {
    SparseTsdfVolume v(o.voxel_m, t);
    for (std::size_t i = 0; i < in.frames.size(); ++i) v.integrate(in.frames[i], in.poses[i]);
    blocks = v.block_count();
    return v.memory_bytes();
  });
  state.counters["blocks"] = double(blocks);
}

void BM_IntegrateDense(benchmark::State& state) {
  const PosedFrames& in = input(int(state.range(0)));
  FusionOptions o;
  const TsdfOptions t = one_thread(in, o);
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < in.frames.size(); ++i) extend_depth_bounds(in.frames[i], in.poses[i], o, box);
  run(state, in, [&] {
    TsdfVolume v(fusion_grid(box, o), t);
    for (std::size_t i = 0; i < in.frames.size(); ++i) v.integrate(in.frames[i], in.poses[i]);
    return v.memory_bytes();
  });
}

void BM_IntegrateOpenVdb(benchmark::State& state) {
  const PosedFrames& in = input(int(state.range(0)));
  FusionOptions o;
  const TsdfOptions t = one_thread(in, o);
  std::size_t leaves = 0;
  run(state, in, [&] {
    OpenVdbTsdf v(o.voxel_m, t);
    for (std::size_t i = 0; i < in.frames.size(); ++i) v.integrate(in.frames[i], in.poses[i]);
    leaves = v.leaf_count();
    return v.memory_bytes();
  });
  state.counters["blocks"] = double(leaves);
}

// Arg 0 = girder, 1 = real indoor.
BENCHMARK(BM_IntegrateSparse)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_IntegrateOpenVdb)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_IntegrateDense)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace tunnelmap::bench
