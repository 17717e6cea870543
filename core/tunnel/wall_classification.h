#pragma once
// Step 1 of tunnel detection: a rough tunnel frame from "up" and the camera's view direction,
// and the assignment of each plane to a wall class by the direction of its (inward) normal.
#include <Eigen/Core>
#include <vector>

#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// Orthonormal, camera frame. forward: camera +Z projected perpendicular to up (rough tunnel
// axis); right = forward x up (equals camera +X for an unrolled, level camera).
struct RoughTunnelFrame {
  Eigen::Vector3d up, forward, right;
};

// `up` must be finite and non-zero (it is normalised here).
RoughTunnelFrame make_rough_frame(const Eigen::Vector3d& up);

// A wall's inward normal: roof points down (-up), floor up, left wall points right, right wall
// points left. Anything further than `class_angle_deg` from all four is Unassigned.
WallClass classify_normal(const RoughTunnelFrame& frame, const Eigen::Vector3d& normal,
                          double class_angle_deg);

std::vector<WallClass> classify_planes(const RoughTunnelFrame& frame, const PlaneSegments& planes,
                                       double class_angle_deg);
// The same, written into `out` (its buffer reused: no allocation per frame in the steady state).
void classify_planes(const RoughTunnelFrame& frame, const PlaneSegments& planes,
                     double class_angle_deg, std::vector<WallClass>& out);

}  // namespace tunnelmap
