#include "core/mapping/walk_facing.h"

#include <cmath>
#include <utility>

namespace tunnelmap {

namespace {

// cos 60 degrees: an axis within 30 degrees of square to the walk.
constexpr double kAcrossTheWalk = 0.5;

WallClass swapped_side(WallClass c) {
  if (c == WallClass::Left) return WallClass::Right;
  if (c == WallClass::Right) return WallClass::Left;
  return c;
}

}  // namespace

bool WalkFacing::looks_back(const TunnelMap& map, const Eigen::Matrix3d& camera_to_world) {
  if (!axis_) axis_ = camera_to_world.col(2);  // the first frame's view, as the stations run
  if (!map.detected) return false;
  const Eigen::Vector3d axis = camera_to_world * map.axis_dir.normalized();
  const double along = axis.dot(*axis_);
  // An axis nearly across the walk is a misfit, not a turn: it neither turns nor leads.
  if (std::abs(along) < kAcrossTheWalk) return false;
  const bool back = along < 0.0;
  axis_ = back ? Eigen::Vector3d(-axis) : axis;
  return back;
}

void turn_round(TunnelMap& map, FrameWalls& walls) {
  // The same stretch seen from its other end: the axis point moves to the far end of the
  // extent, which stays as it is (the wall geometry is rebuilt from the axis point on).
  map.axis_point += (map.extent_min_m + map.extent_max_m) * map.axis_dir;
  map.axis_dir = -map.axis_dir;
  std::swap(map.walls[0], map.walls[1]);
  map.walls[0].cls = WallClass::Left;
  map.walls[1].cls = WallClass::Right;
  for (WallClass& c : map.plane_classes) c = swapped_side(c);
  for (WallClass& c : map.plane_candidate_classes) c = swapped_side(c);
  for (WallSample& s : walls.samples)
    if (s.wall < 2) s.wall = static_cast<std::uint8_t>(1 - s.wall);
}

}  // namespace tunnelmap
