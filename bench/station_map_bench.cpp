// The map of the whole tunnel on top of per-frame detection: a 20-frame posed walk over three
// sections is detected once; the benchmark then builds the station map from those results
// (context step per frame in order, then the sections). Counter "map_ms_per_frame" is the cost
// `map` adds per frame beyond detection (budget: 25 ms on one core).
//   tunnelmap_bench --benchmark_filter=StationMap
// The dataset is written once to $TMPDIR/tunnelmap-station-map-bench (reused afterwards).
#include <benchmark/benchmark.h>

#include <chrono>
#include <filesystem>

#include "core/fusion/fusion_options.h"
#include "core/io/dataset.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/station_map_builder.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/build_paths.h"

namespace tunnelmap::bench {
namespace {

std::string walk_dataset() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "tunnelmap-station-map-bench";
  if (!fs::exists(dir / "dataset.json")) {
    SimConfig c = SimConfig::from_preset("lab");
    c.frames = 20;
    c.seed = 5;
    c.sections = {{1.5, 0.84, 1.30}, {1.5, 0.80, 1.28}, {2.0, 0.82, 1.32}};
    SimWalk walk;
    walk.start_x_m = -1.0;
    walk.end_x_m = 3.0;
    walk.stops = 5;
    walk.pose.z_rel = 0.5;
    c.walk = walk;
    write_sim_dataset(dir.string(), c);
  }
  return dir.string();
}

void BM_StationMap(benchmark::State& state) {
  const Dataset ds = read_dataset(walk_dataset());
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/lab.json");
  Pipeline pipeline(params);
  pipeline.set_world_up(ds.up);
  std::vector<FrameResult> results(ds.frames.size());
  std::vector<Eigen::Isometry3d> poses;
  FrameScratch scratch;  // one for all frames: the kept results hold no buffers
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const DepthFrame f = ds.load_frame(i);
    pipeline.run(f, results[i], scratch);
    poses.push_back(*f.pose);
  }
  const std::vector<TunnelMap> detected = [&] {
    std::vector<TunnelMap> m;
    for (const FrameResult& r : results) m.push_back(r.map);
    return m;
  }();
  const std::vector<int> groups = group_poses(poses, fusion_options(params).pose_group_m);
  std::size_t sections = 0, frames = 0;
  double ms = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    StationMapBuilder builder(station_map_options(params), tunnel_options(params));
    for (std::size_t i = 0; i < results.size(); ++i) {
      results[i].map = detected[i];  // the context step rewrites it
      FrameWalls walls;
      extract_frame_walls(results[i], walls);  // part of the map's cost beyond detection
      builder.add_frame(static_cast<int>(i), results[i].map, walls, poses[i]);
    }
    const StationMap map = builder.finish(groups);
    sections = map.sections.size();
    benchmark::DoNotOptimize(map.stations.data());
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    frames += results.size();
  }
  state.counters["map_ms_per_frame"] = frames ? ms / frames : 0.0;
  state.counters["sections"] = static_cast<double>(sections);
}

BENCHMARK(BM_StationMap)->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace
}  // namespace tunnelmap::bench
