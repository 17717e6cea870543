#pragma once
// The simulated eye-in-hand arm: turns a wanted camera pose into joints (IK) and the true,
// sagged camera pose the frame is rendered from. Only used when SimConfig::arm_preset is set.
#include <Eigen/Geometry>
#include <vector>

#include "core/kinematics/robot_model.h"
#include "core/sim/sim_config.h"

namespace tunnelmap {

struct SimArmState {
  std::vector<double> joints;  // rad
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();       // world <- robot base
  Eigen::Isometry3d fk_pose = Eigen::Isometry3d::Identity();    // 0T_s(q): what the joints say
  Eigen::Isometry3d true_pose = Eigen::Isometry3d::Identity();  // with link sag
  double ik_error_m = 0.0;                                      // |fk_pose - wanted| position
};

// The robot with its base on the floor centre line, `arm_setback_m` behind `group_x`.
RobotModel sim_robot(const SimConfig& config, double group_x);
// Throws ParameterError when the arm cannot reach `wanted` (error > 1 mm or 0.1 deg).
SimArmState solve_sim_arm(const SimConfig& config, double group_x, const Eigen::Isometry3d& wanted);

}  // namespace tunnelmap
