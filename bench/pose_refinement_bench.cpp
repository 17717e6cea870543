// Pose refinement against the tunnel map beside the fusion it serves: a 30-frame lab sequence of
// the eye-in-hand arm with 2 deg/m of sag. BM_PoseRefinement times refine_poses alone on the
// frames' detections (counter "refine_ms"); BM_FuseWithRefinement times the whole fuse_dataset
// (counters "fuse_ms" and "refine_share_pct", the refinement's share of it: budget 20 %).
//   tunnelmap_bench --benchmark_filter=Refinement
// The dataset is written once to $TMPDIR/tunnelmap-refinement-bench (reused afterwards).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/io/dataset.h"
#include "core/kinematics/frame_pose.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/pose_refinement.h"
#include "core/sim/sim_dataset_writer.h"

namespace tunnelmap::bench {
namespace {

std::string sag_dataset() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "tunnelmap-refinement-bench";
  if (!fs::exists(dir / "dataset.json")) {
    SimConfig c = SimConfig::from_preset("lab");
    c.frames = 30;
    c.seed = 11;
    c.arm_preset = "inchworm7";
    c.arm_sag_deg_per_m = 2.0;
    write_sim_dataset(dir.string(), c);
  }
  return dir.string();
}

Parameters lab_params() {
  Parameters p;
  p.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  return p;
}

void BM_PoseRefinement(benchmark::State& state) {
  const Dataset ds = read_dataset(sag_dataset());
  const Parameters params = lab_params();
  Pipeline pipeline(params);
  pipeline.set_world_up(ds.up);
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> poses;
  FrameResult r;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    DepthFrame f = ds.load_frame(i);
    f.pose = *resolve_frame_pose(ds, i).pose;
    pipeline.run(f, r);
    walls.emplace_back();
    extract_frame_walls(r, walls.back());
    maps.push_back(r.map);
    poses.push_back(*f.pose);
  }
  const std::vector<int> groups = group_poses(poses, fusion_options(params).pose_group_m);
  double ms = 0.0;
  int runs = 0, iterations = 0;
  for (auto _ : state) {
    const PoseRefinement p = refine_poses(maps, walls, poses, groups);
    ms += p.ms;
    iterations = p.iterations;
    ++runs;
    benchmark::DoNotOptimize(p.poses.data());
  }
  state.counters["refine_ms"] = runs ? ms / runs : 0.0;
  state.counters["iterations"] = iterations;
  state.counters["frames"] = static_cast<double>(poses.size());
}

void BM_FuseWithRefinement(benchmark::State& state) {
  const Dataset ds = read_dataset(sag_dataset());
  const Parameters params = lab_params();
  FuseSettings s;
  s.threads = 1;
  double fuse_ms = 0.0, refine_ms = 0.0;
  int runs = 0;
  for (auto _ : state) {
    const FusionResult r = fuse_dataset(ds, params, s);
    fuse_ms += r.timings_ms.at("total");
    refine_ms += r.refinement.ms;
    ++runs;
  }
  state.counters["fuse_ms"] = runs ? fuse_ms / runs : 0.0;
  state.counters["refine_share_pct"] = fuse_ms > 0 ? 100.0 * refine_ms / fuse_ms : 0.0;
}

BENCHMARK(BM_PoseRefinement)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_FuseWithRefinement)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
}  // namespace tunnelmap::bench
