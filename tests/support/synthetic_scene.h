#pragma once
// Exact ray-cast depth frames of simple analytic scenes (planes, a box room) for unit tests of
// the geometric stages, independent of the tunnel simulator.
#include <Eigen/Geometry>
#include <vector>

#include "core/frame/depth_frame.h"

namespace tunnelmap::test {

struct AnalyticPlane {
  Eigen::Vector3d normal;  // unit, world frame
  double offset;           // normal.dot(x) + offset = 0
};

struct SyntheticFrame {
  DepthFrame frame;           // depth in millimetres as float (no quantisation unless asked)
  std::vector<int> plane_id;  // per pixel: index into the scene's planes, -1 = nothing
};

// The camera (pose = camera-to-world) sees the nearest plane hit in front of it whose hit point
// lies inside `bounds_min..bounds_max` (inflated slightly). `noise_m` adds Gaussian depth noise.
SyntheticFrame render_planes(const std::vector<AnalyticPlane>& planes, const Eigen::Isometry3d& pose,
                             const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max,
                             double noise_m = 0.0, unsigned seed = 1,
                             const Intrinsics& K = Intrinsics::primesense_vga());

// A closed box room [min, max]: six inward-facing planes, in the order -x, +x, -y, +y, -z, +z.
std::vector<AnalyticPlane> box_room(const Eigen::Vector3d& min, const Eigen::Vector3d& max);

// Camera at `eye` looking at `target` with world +Z as up (image y down).
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ());

}  // namespace tunnelmap::test
