// Localisation and mapping against the structure (StructureSlam) on the frames' detections:
//   BM_StructureSlamGirder  a 40 m girder with diaphragms every 4 m and drifting odometry,
//                           120 frames: counters "ms_per_frame" (each frame's window, the robot
//                           on the move; budget 10 ms), "batch_ms" and "batch_iterations" (the
//                           final optimisation) and "landmarks".
//   BM_StructureSlamGirderImu the same walk with an IMU's gravity (0.1 degrees) on every frame.
//   BM_FuseWithRefinement   the whole fuse_dataset of a 30-frame lab arm sequence with 2 deg/m of
//                           sag: "fuse_ms" and "refine_share_pct" (budget 20 %).
//   tunnelmap_bench --benchmark_filter='StructureSlam|Refinement'
// The datasets are written once to $TMPDIR/tunnelmap-slam-bench-* (reused afterwards).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/io/dataset.h"
#include "core/kinematics/frame_pose.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/structure_slam.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"

namespace tunnelmap::bench {
namespace {

std::string dataset(const char* name, const SimConfig& c) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / (std::string("tunnelmap-slam-bench-") + name);
  if (!fs::exists(dir / "dataset.json")) write_sim_dataset(dir.string(), c);
  return dir.string();
}

std::string sag_dataset() {
  SimConfig c = SimConfig::from_preset("lab");
  c.frames = 30;
  c.seed = 11;
  c.arm_preset = "inchworm7";
  c.arm_sag_deg_per_m = 2.0;
  return dataset("sag", c);
}

std::string girder_dataset(double imu_gravity_deg) {
  SimConfig c = SimConfig::from_preset("field");
  c.seed = 7;
  c.girder_length_m = 40.0;
  c.diaphragm_spacing_m = 4.0;
  c.frames = 120;
  c.drift_translation_mm_per_sqrt_m = 10.0;
  c.drift_rotation_deg_per_sqrt_m = 0.2;
  c.manhole_distances_m.clear();  // the girder's plates are its diaphragms
  SimWalk walk;  // one stop per frame, through every manhole (as `simulate --girder` walks)
  walk.start_x_m = 0.5;
  walk.end_x_m = 39.5;
  walk.stops = c.frames;
  walk.pose = SimCameraPose{0.0, 0.5, 0.0, 0.0, 0.0};
  walk.through_openings = true;
  c.walk = walk;
  c.imu_gravity_deg = imu_gravity_deg;
  return dataset(imu_gravity_deg > 0.0 ? "girder-walk-imu" : "girder-walk", c);
}

Parameters preset(const char* name) {
  Parameters p;
  p.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/" + name + ".json");
  return p;
}

void run_girder_slam(benchmark::State& state, const Dataset& ds) {
  const Parameters params = preset("field");
  Pipeline pipeline(params);
  pipeline.set_world_up(ds.up);
  std::vector<TunnelMap> maps;
  std::vector<FrameWalls> walls;
  std::vector<Eigen::Isometry3d> poses;
  std::vector<std::optional<Eigen::Vector3d>> gravity;
  FrameResult r;
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    DepthFrame f = ds.load_frame(i);
    f.pose = *resolve_frame_pose(ds, i).pose;
    pipeline.run(f, r);
    walls.emplace_back();
    extract_frame_walls(r, walls.back());
    maps.push_back(r.map);
    poses.push_back(*f.pose);
    gravity.push_back(f.gravity);
  }
  const std::vector<int> groups = group_poses(poses, fusion_options(params).pose_group_m);
  double frames_ms = 0.0, worst_frame_ms = 0.0, batch_ms = 0.0;
  int runs = 0, landmarks = 0, batch_iterations = 0;
  for (auto _ : state) {
    StructureSlam slam(slam_options(params));
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < maps.size(); ++i) {
      slam.add_frame(maps[i], walls[i], poses[i], groups[i], gravity[i]);
      worst_frame_ms = std::max(worst_frame_ms, slam.last_frame_ms());
    }
    const auto t1 = std::chrono::steady_clock::now();
    const PoseRefinement p = slam.finish();
    frames_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    batch_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
    landmarks = slam.landmarks();
    batch_iterations = p.iterations;
    ++runs;
    benchmark::DoNotOptimize(p.poses.data());
  }
  state.counters["ms_per_frame"] = runs ? frames_ms / runs / static_cast<double>(maps.size()) : 0.0;
  state.counters["worst_frame_ms"] = worst_frame_ms;
  state.counters["batch_ms"] = runs ? batch_ms / runs : 0.0;
  state.counters["landmarks"] = landmarks;
  state.counters["batch_iterations"] = batch_iterations;
  state.counters["frames"] = static_cast<double>(poses.size());
}

void BM_StructureSlamGirder(benchmark::State& state) { run_girder_slam(state, read_dataset(girder_dataset(0.0))); }

void BM_StructureSlamGirderImu(benchmark::State& state) {
  run_girder_slam(state, read_dataset(girder_dataset(0.1)));
}

void BM_FuseWithRefinement(benchmark::State& state) {
  const Dataset ds = read_dataset(sag_dataset());
  Parameters params = preset("lab");
  params.set("slam.odometry_deg_per_sqrt_m", 2.0);  // the arm's sag, as its user states it
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

BENCHMARK(BM_StructureSlamGirder)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_StructureSlamGirderImu)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_FuseWithRefinement)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
}  // namespace tunnelmap::bench
