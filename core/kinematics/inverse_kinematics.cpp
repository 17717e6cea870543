#include "core/kinematics/inverse_kinematics.h"

#include <algorithm>

namespace tunnelmap {

namespace {
// 6-vector error (position; rotation as angle-axis) taking `current` to `target`, world frame.
Eigen::Matrix<double, 6, 1> pose_error(const Eigen::Isometry3d& current,
                                       const Eigen::Isometry3d& target) {
  Eigen::Matrix<double, 6, 1> e;
  e.head<3>() = target.translation() - current.translation();
  const Eigen::AngleAxisd aa(target.linear() * current.linear().transpose());
  e.tail<3>() = aa.axis() * aa.angle();
  return e;
}
}  // namespace

IkResult solve_camera_ik(const RobotModel& robot, const Eigen::Isometry3d& target,
                         std::vector<double> q, int max_iterations) {
  const int n = robot.dof();
  if (static_cast<int>(q.size()) != n) q.assign(static_cast<std::size_t>(n), 0.0);
  const double h = 1e-7, lambda = 0.02;
  IkResult r;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::Isometry3d T = robot.camera_pose(q);
    const Eigen::Matrix<double, 6, 1> e = pose_error(T, target);
    r.position_error_m = e.head<3>().norm();
    r.rotation_error_rad = e.tail<3>().norm();
    if (r.position_error_m < 1e-6 && r.rotation_error_rad < 1e-6) {
      r.converged = true;
      break;
    }
    Eigen::MatrixXd J(6, n);
    for (int k = 0; k < n; ++k) {
      std::vector<double> qk = q;
      qk[k] += h;
      J.col(k) = -pose_error(robot.camera_pose(qk), T) / h;
    }
    // dq = J^T (J J^T + lambda^2 I)^-1 e, step limited to 0.2 rad per joint.
    const Eigen::Matrix<double, 6, 6> A =
        J * J.transpose() + lambda * lambda * Eigen::Matrix<double, 6, 6>::Identity();
    const Eigen::VectorXd dq = J.transpose() * A.ldlt().solve(e);
    const double scale = std::min(1.0, 0.2 / std::max(1e-12, dq.cwiseAbs().maxCoeff()));
    for (int k = 0; k < n; ++k)
      q[k] = std::clamp(q[k] + scale * dq[k], robot.joints[k].min, robot.joints[k].max);
  }
  r.q = q;
  return r;
}

}  // namespace tunnelmap
