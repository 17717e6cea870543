#include "core/mapping/posed_sequence.h"

#include <chrono>
#include <map>
#include <utility>

#include "core/fusion/fusion_options.h"
#include "core/mapping/centreline_fit.h"
#include "core/mapping/multi_scan_map.h"
#include "core/mapping/station_map_builder.h"
#include "core/mapping/structure_slam.h"
#include "core/mapping/walk_facing.h"

namespace tunnelmap {

namespace {

// Stations along the centre line fitted to the frames' cross-section centres, counted from the
// first frame's camera in its viewing direction (as along a straight axis). A walk too short to
// fit keeps the first frame's axis.
void follow_fitted_centreline(StationMapBuilder& builder, const std::vector<TunnelMap>& maps,
                              const std::vector<Eigen::Isometry3d>& poses, const StationMapOptions& options) {
  if (poses.empty()) return;
  const std::optional<Centreline> line = fit_centreline(centre_samples(maps, poses), poses.front().translation(),
                                                        poses.front().linear().col(2), options);
  if (line) builder.follow(*line);
}

// The frames that look back along the walk, turned round (core/mapping/walk_facing.h), by index;
// decided on the given poses, which are off by degrees at most.
std::map<std::size_t, std::pair<TunnelMap, FrameWalls>> turned_frames(const std::vector<TunnelMap>& maps,
                                                                      const std::vector<FrameWalls>& walls,
                                                                      const std::vector<Eigen::Isometry3d>& poses) {
  std::map<std::size_t, std::pair<TunnelMap, FrameWalls>> turned;
  WalkFacing facing;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (!facing.looks_back(maps[i], poses[i].linear())) continue;
    auto& [map, frame_walls] = turned[i] = {maps[i], walls[i]};
    turn_round(map, frame_walls);
  }
  return turned;
}

}  // namespace

MappedSequence map_posed_sequence(std::vector<TunnelMap>& maps, const std::vector<FrameWalls>& walls,
                                  const std::vector<Eigen::Isometry3d>& poses, const Eigen::Vector3d& world_up,
                                  const Parameters& params, bool refine,
                                  const std::vector<std::optional<Eigen::Vector3d>>& gravity) {
  const auto t0 = std::chrono::steady_clock::now();
  MappedSequence out;
  out.groups = group_poses(poses, fusion_options(params).pose_group_m);
  out.poses = poses;
  const StationMapOptions so = station_map_options(params);
  auto turned = turned_frames(maps, walls, poses);
  auto map_of = [&](std::size_t i) -> TunnelMap& {
    const auto it = turned.find(i);
    return it == turned.end() ? maps[i] : it->second.first;
  };
  auto walls_of = [&](std::size_t i) -> const FrameWalls& {
    const auto it = turned.find(i);
    return it == turned.end() ? walls[i] : it->second.second;
  };
  if (refine) {
    SlamOptions slam_opts = slam_options(params);
    slam_opts.world_up = world_up;
    StructureSlam slam(slam_opts);
    for (std::size_t i = 0; i < maps.size(); ++i)
      slam.add_frame(map_of(i), walls_of(i), poses[i], out.groups[i], i < gravity.size() ? gravity[i] : std::nullopt);
    out.refinement = slam.finish();
    if (out.refinement.ran) out.poses = out.refinement.poses;
  }
  StationMapBuilder builder(so, tunnel_options(params));
  builder.set_unchecked_frames(frames_nothing_checks(out.refinement));
  if (so.follow_centreline) follow_fitted_centreline(builder, maps, out.poses, so);
  for (std::size_t i = 0; i < maps.size(); ++i)
    builder.add_frame(static_cast<int>(i), map_of(i), walls_of(i), out.poses[i]);
  // The builder fills in what the context gives (parts, inferred walls): back to the frame's own view.
  for (auto& [i, frame] : turned) {
    turn_round(frame.first, frame.second);
    maps[i] = std::move(frame.first);
  }
  out.stations = builder.finish(out.groups);
  out.map_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace tunnelmap
