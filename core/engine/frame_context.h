#pragma once
// The context rule, the same for every front end: a posed frame takes its context from the
// station map along the tunnel (world frame, follows sections that change); a frame without a
// pose from the widths of the recent frames. Applied in frame order, after the frame's own
// detection, so detection itself may run on several threads. With `slam.localise`, a posed
// frame is first localised against the structure mapped so far (StructureSlam, its window of
// recent poses) and mapped with that pose.
#include <optional>

#include "core/mapping/station_map_builder.h"
#include "core/mapping/structure_slam.h"
#include "core/mapping/walk_facing.h"
#include "core/pipeline/pipeline.h"
#include "core/tunnel/tunnel_detector.h"

namespace tunnelmap {

class FrameContext {
 public:
  // `world_up`: the posed frames' world up (the dataset's).
  FrameContext(const Parameters& params, const Eigen::Vector3d& world_up);

  // Frame `index`'s result (detected without context) gets the context of the frames before it,
  // then becomes part of the context of the frames after it. Returns the pose it was mapped
  // with: the given one, or where localisation put it.
  // `gravity`: where things fall in the camera's frame, when an IMU tells it (localisation).
  std::optional<Eigen::Isometry3d> apply(int index, FrameResult& result, const std::optional<Eigen::Isometry3d>& pose,
                                         const std::optional<Eigen::Vector3d>& gravity = std::nullopt);

  // For a method that checks the context inside its own fit (the convex-hull baseline).
  TunnelContext& recent() { return recent_; }
  const StationMapBuilder& stations() const { return stations_; }

 private:
  Eigen::Isometry3d localise(const TunnelMap& map, const FrameWalls& walls, const Eigen::Isometry3d& pose,
                             const std::optional<Eigen::Vector3d>& gravity);

  TunnelOptions tunnel_;
  TunnelContext recent_;
  StationMapBuilder stations_;
  WalkFacing facing_;
  std::optional<StructureSlam> slam_;  // with slam.localise
  double pose_group_m_ = 0.0;
  int group_ = -1;
  Eigen::Isometry3d group_first_ = Eigen::Isometry3d::Identity();  // the group's first given pose
};

}  // namespace tunnelmap
