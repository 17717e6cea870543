#pragma once
// The mapping of a posed sequence after per-frame detection, shared by `map` and `fuse`: pose
// groups, pose refinement against the map (unless turned off), then the station map built in
// frame order with the refined poses, each frame's map getting its context (walls inferred
// from the map, frames inconsistent with it rejected).
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/mapping/frame_walls.h"
#include "core/mapping/pose_refinement.h"
#include "core/mapping/station_map.h"
#include "core/params/parameters.h"

namespace tunnelmap {

struct MappedSequence {
  std::vector<int> groups;                 // pose group per frame
  PoseRefinement refinement;               // ran == false when turned off or nothing detected
  std::vector<Eigen::Isometry3d> poses;    // per frame: refined, else as given
  StationMap stations;
  double map_ms = 0.0;                     // refinement + station map
};

// `maps[i]`: frame i's detection without context (updated in place with it); `walls[i]` its
// samples (extract_frame_walls); `poses[i]` its forward-kinematics or explicit pose, in a world
// whose up is `world_up`. `gravity[i]` (empty, or one per frame): where things fall in frame
// i's camera frame, when an IMU tells it.
MappedSequence map_posed_sequence(std::vector<TunnelMap>& maps, const std::vector<FrameWalls>& walls,
                                  const std::vector<Eigen::Isometry3d>& poses, const Eigen::Vector3d& world_up,
                                  const Parameters& params, bool refine,
                                  const std::vector<std::optional<Eigen::Vector3d>>& gravity = {});

}  // namespace tunnelmap
