#pragma once
// Frames that look back along the walk. A single frame's template points its axis the way its
// camera looks and names the wall on the camera's left `Left`; an eye-in-hand camera turned
// round to look back along the girder thus sees the girder's right wall as its `Left`. Mapping
// names walls as the walk does, so such a frame is turned round first.
#include <optional>

#include <Eigen/Core>

#include "core/mapping/frame_walls.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

class WalkFacing {
 public:
  // Whether the frame, posed at `camera_to_world`, looks back along the walk; called once per
  // frame in the walk's order. The walk goes the way the first frame looks (as the stations
  // run) and then follows each detected frame's axis, so a girder that curves keeps its
  // direction. A frame without a cross-section, or whose axis lies within 30 degrees of square
  // to the walk (a misfit, not a turn), is never turned round and does not lead.
  bool looks_back(const TunnelMap& map, const Eigen::Matrix3d& camera_to_world);

 private:
  std::optional<Eigen::Vector3d> axis_;  // world: the way the walk goes
};

// The frame as seen facing the other way: its axis reversed from the far end of its extent (the
// same stretch), its left and right walls (and their planes and samples) swapped. Turning twice
// gives the frame back.
void turn_round(TunnelMap& map, FrameWalls& walls);

}  // namespace tunnelmap
