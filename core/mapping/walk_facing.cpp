#include "core/mapping/walk_facing.h"

#include <utility>

namespace tunnelmap {

namespace {

WallClass swapped_side(WallClass c) {
  if (c == WallClass::Left) return WallClass::Right;
  if (c == WallClass::Right) return WallClass::Left;
  return c;
}

}  // namespace

bool WalkFacing::looks_back(const TunnelMap& map, const Eigen::Matrix3d& camera_to_world) {
  if (!map.detected) return false;
  const Eigen::Vector3d axis = camera_to_world * map.axis_dir.normalized();
  if (!axis_) axis_ = axis;  // the template points its axis the way the camera looks
  const bool back = axis.dot(*axis_) < 0.0;
  axis_ = back ? Eigen::Vector3d(-axis) : axis;
  return back;
}

void turn_round(TunnelMap& map, FrameWalls& walls) {
  map.axis_dir = -map.axis_dir;
  map.extent_min_m = -std::exchange(map.extent_max_m, -map.extent_min_m);
  std::swap(map.walls[0], map.walls[1]);
  map.walls[0].cls = WallClass::Left;
  map.walls[1].cls = WallClass::Right;
  for (WallClass& c : map.plane_classes) c = swapped_side(c);
  for (WallClass& c : map.plane_candidate_classes) c = swapped_side(c);
  for (WallSample& s : walls.samples)
    if (s.wall < 2) s.wall = static_cast<std::uint8_t>(1 - s.wall);
}

}  // namespace tunnelmap
