#include "core/sim/sim_arm.h"

#include <cmath>
#include <string>

#include "core/kinematics/inverse_kinematics.h"
#include "core/kinematics/sag_model.h"
#include "core/util/error.h"

namespace tunnelmap {

RobotModel sim_robot(const SimConfig& config, double group_x) {
  RobotModel r = robot_preset(config.arm_preset);
  r.base.translation() = Eigen::Vector3d(group_x - config.arm_setback_m, 0.0, 0.0);
  return r;
}

SimArmState solve_sim_arm(const SimConfig& config, double group_x, const Eigen::Isometry3d& wanted) {
  const RobotModel robot = sim_robot(config, group_x);
  IkResult best;
  best.position_error_m = INFINITY;
  // A few seeds (elbow up at different bends) so one bad start does not fail the frame.
  std::vector<double> seed = robot_home(robot);
  for (int attempt = 0; attempt < 4; ++attempt) {
    if (attempt > 0 && seed.size() == 7) {
      seed[1] = 0.3 * attempt;
      seed[3] = 0.6 + 0.4 * attempt;
      seed[5] = 0.4 * attempt;
    }
    IkResult r = solve_camera_ik(robot, wanted, seed);
    if (r.position_error_m + r.rotation_error_rad < best.position_error_m + best.rotation_error_rad)
      best = r;
    if (best.converged) break;
  }
  if (best.position_error_m > 1e-3 || best.rotation_error_rad > 0.1 * M_PI / 180.0)
    throw ParameterError("simulator: arm '" + config.arm_preset + "' cannot reach a camera pose (" +
                         std::to_string(best.position_error_m * 1000.0) +
                         " mm off); reduce arm_setback_m or move the pose");
  SimArmState s;
  s.joints = best.q;
  s.base = robot.base;
  s.fk_pose = robot.camera_pose(s.joints);
  SagModel sag;
  sag.deg_per_m = config.arm_sag_deg_per_m;
  s.true_pose = sagged_camera_pose(robot, s.joints, sag);
  s.ik_error_m = best.position_error_m;
  return s;
}

}  // namespace tunnelmap
