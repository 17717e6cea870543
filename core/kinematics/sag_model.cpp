#include "core/kinematics/sag_model.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap {

Eigen::Isometry3d sagged_camera_pose(const RobotModel& robot, const std::vector<double>& q,
                                     const SagModel& sag) {
  const std::vector<Eigen::Isometry3d> frames = robot.joint_frames(q);
  const Eigen::Isometry3d cam = frames.back() * robot.tool_to_camera;
  if (sag.deg_per_m == 0.0) return cam;
  const int k = std::clamp(sag.pivot_frame, 0, static_cast<int>(frames.size()) - 1);
  const Eigen::Vector3d pivot = frames[static_cast<std::size_t>(k)].translation();
  const Eigen::Vector3d up = sag.up.normalized();
  const Eigen::Vector3d reach = cam.translation() - pivot;
  const Eigen::Vector3d reach_h = reach - up * up.dot(reach);
  const double lh = reach_h.norm();
  if (lh < 1e-9) return cam;
  // Positive rotation about (reach_h x up) lifts the tip; droop is the negative angle.
  const Eigen::Vector3d axis = reach_h.cross(up).normalized();
  const double theta = -sag.deg_per_m * M_PI / 180.0 * lh;
  Eigen::Isometry3d R = Eigen::Isometry3d::Identity();
  R.linear() = Eigen::AngleAxisd(theta, axis).toRotationMatrix();
  R.translation() = pivot - R.linear() * pivot;
  return R * cam;
}

}  // namespace tunnelmap
