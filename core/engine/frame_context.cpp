#include "core/engine/frame_context.h"

#include "core/fusion/fusion_options.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/map_options.h"
#include "core/mapping/walk_facing.h"

namespace tunnelmap {

namespace {

constexpr double kGroupTurnDeg = 5.0;  // as group_poses groups a whole sequence

}  // namespace

FrameContext::FrameContext(const Parameters& params, const Eigen::Vector3d& world_up)
    : tunnel_(tunnel_options(params)),
      stations_(station_map_options(params), tunnel_),
      pose_group_m_(fusion_options(params).pose_group_m) {
  SlamOptions slam = slam_options(params);
  slam.world_up = world_up;
  if (slam.localise) slam_.emplace(slam);
}

std::optional<Eigen::Isometry3d> FrameContext::apply(int index, FrameResult& result,
                                                     const std::optional<Eigen::Isometry3d>& pose,
                                                     const std::optional<Eigen::Vector3d>& gravity) {
  if (pose) {
    FrameWalls walls;
    extract_frame_walls(result, walls);  // a frame with no cross-section may still see a plate
    // Mapped facing along the walk; the frame's own result keeps its own view.
    const bool looks_back = facing_.looks_back(result.map, pose->linear());
    if (looks_back) turn_round(result.map, walls);
    const Eigen::Isometry3d mapped_with = slam_ ? localise(result.map, walls, *pose, gravity) : *pose;
    stations_.add_frame(index, result.map, walls, mapped_with);
    if (looks_back) turn_round(result.map, walls);
    return mapped_with;
  }
  apply_tunnel_context(result.map, tunnel_, recent_);
  if (result.map.detected) recent_.accept(result.map);
  return pose;
}

// The frame's pose group (a new one when the given pose moved or turned past the grouping
// limits from the group's first), then its pose as the structure so far places it.
Eigen::Isometry3d FrameContext::localise(const TunnelMap& map, const FrameWalls& walls, const Eigen::Isometry3d& pose,
                                         const std::optional<Eigen::Vector3d>& gravity) {
  const Eigen::Isometry3d d = group_first_.inverse() * pose;
  const double turn_deg = Eigen::AngleAxisd(d.linear()).angle() * 180.0 / M_PI;
  if (group_ < 0 || d.translation().norm() > pose_group_m_ || turn_deg > kGroupTurnDeg) {
    ++group_;
    group_first_ = pose;
  }
  return slam_->add_frame(map, walls, pose, group_, gravity);
}

}  // namespace tunnelmap
