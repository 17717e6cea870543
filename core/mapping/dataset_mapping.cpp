#include "core/mapping/dataset_mapping.h"

#include <chrono>

#include "core/engine/run_engine.h"
#include "core/kinematics/frame_pose.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/slam_options.h"
#include "core/util/error.h"

namespace tunnelmap {

std::vector<Eigen::Isometry3d> dataset_poses(const Dataset& ds) {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(ds.frames.size());
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const ResolvedPose rp = resolve_frame_pose(ds, i);
    if (!rp.pose)
      throw InputError(ds.json_path, "frames[" + std::to_string(i) +
                                         "] has neither \"pose\" nor \"joints\": the map needs "
                                         "every camera pose");
    poses.push_back(*rp.pose);
  }
  return poses;
}

std::vector<std::optional<Eigen::Vector3d>> dataset_gravity(const Dataset& ds) {
  std::vector<std::optional<Eigen::Vector3d>> out;
  for (const DatasetFrameRef& f : ds.frames) out.push_back(f.gravity);
  return out;
}

DatasetMapping map_dataset(const Dataset& ds, Pipeline& pipeline, bool refine_poses,
                           const MappingProgress& progress) {
  const std::size_t n = ds.frames.size();
  if (n == 0) throw InputError(ds.json_path, "the dataset has no frames");
  const std::vector<Eigen::Isometry3d> poses = dataset_poses(ds);
  pipeline.set_world_up(ds.up);

  DatasetMapping out;
  out.maps.resize(n);
  out.sources.resize(n);
  out.plane_counts.resize(n);
  out.timings.resize(n);
  std::vector<FrameWalls> walls(n);
  double extract_ms = 0.0;
  // Frames detected without context (the map gives it afterwards), each with its pose for up.
  RunSettings settings;
  settings.params = pipeline.params();
  settings.camera_up = pipeline.camera_up();
  const PosedFrames frames(ds, poses);
  RunEngine engine(settings, &frames, RunEngine::ContextRule::None);
  engine.run(frames, [&](SequenceFrame& f) {
    if (!f.ok()) std::rethrow_exception(f.error);  // the frame's InputError
    const std::size_t k = f.index;
    const FrameResult& result = f.result;
    out.detect_ms += result.timings_ms.at("total");
    const auto t_extract = std::chrono::steady_clock::now();
    extract_frame_walls(result, walls[k]);
    extract_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_extract).count();
    out.maps[k] = result.map;
    out.sources[k] = f.frame.source;
    out.plane_counts[k] = result.planes.planes.size();
    out.timings[k] = result.timings_ms;
    out.cancelled = progress && !progress(k + 1);
    return !out.cancelled;
  });
  if (out.cancelled) return out;
  const std::vector<std::optional<Eigen::Vector3d>> gravity = dataset_gravity(ds);
  out.mapped = map_posed_sequence(out.maps, walls, poses, ds.up, pipeline.params(), refine_poses, gravity);
  out.notes = mapping_notes(out.mapped, gravity, ds.up, pipeline.params().get(slam_keys::gravity_deg));
  out.map_ms = out.mapped.map_ms + extract_ms;
  out.mapped.stations.timings_ms["map"] = out.map_ms;
  return out;
}

}  // namespace tunnelmap
