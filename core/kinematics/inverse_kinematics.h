#pragma once
// Damped-least-squares inverse kinematics for the camera pose (used by the simulator to turn a
// wanted camera pose into a joint vector). Numeric Jacobian: the arms here have <= 10 joints.
#include <vector>

#include "core/kinematics/robot_model.h"

namespace tunnelmap {

struct IkResult {
  std::vector<double> q;
  double position_error_m = 0.0;
  double rotation_error_rad = 0.0;
  bool converged = false;  // within 1e-6 m and 1e-6 rad
};

// Starts at `seed`; keeps joints within their limits.
IkResult solve_camera_ik(const RobotModel& robot, const Eigen::Isometry3d& target,
                         std::vector<double> seed, int max_iterations = 300);

}  // namespace tunnelmap
