#include "core/kinematics/robot_model.h"

#include <cmath>

#include "core/util/error.h"

namespace tunnelmap {

namespace {
constexpr double kDeg = M_PI / 180.0;

Eigen::Isometry3d rot_z(double t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}
Eigen::Isometry3d rot_x(double t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(t, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return T;
}
Eigen::Isometry3d trans(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}
}  // namespace

Eigen::Isometry3d RobotModel::link_transform(int i, double q) const {
  const DhJoint& j = joints.at(static_cast<std::size_t>(i));
  const bool revolute = j.type == JointType::Revolute;
  const double theta = j.theta_rad + (revolute ? q : 0.0);
  const double d = j.d_m + (revolute ? 0.0 : q);
  if (convention == DhConvention::Standard)
    return rot_z(theta) * trans(0, 0, d) * trans(j.a_m, 0, 0) * rot_x(j.alpha_rad);
  return rot_x(j.alpha_rad) * trans(j.a_m, 0, 0) * rot_z(theta) * trans(0, 0, d);
}

std::vector<Eigen::Isometry3d> RobotModel::joint_frames(const std::vector<double>& q) const {
  if (static_cast<int>(q.size()) != dof())
    throw ParameterError("robot '" + name + "': " + std::to_string(q.size()) +
                         " joint values for a " + std::to_string(dof()) + "-DOF arm");
  std::vector<Eigen::Isometry3d> frames{base};
  for (int i = 0; i < dof(); ++i) frames.push_back(frames.back() * link_transform(i, q[i]));
  return frames;
}

Eigen::Isometry3d RobotModel::flange_pose(const std::vector<double>& q) const {
  return joint_frames(q).back();
}

Eigen::Isometry3d RobotModel::camera_pose(const std::vector<double>& q) const {
  return flange_pose(q) * tool_to_camera;
}

int RobotModel::first_joint_out_of_limits(const std::vector<double>& q) const {
  for (int i = 0; i < dof() && i < static_cast<int>(q.size()); ++i)
    if (q[i] < joints[i].min - 1e-9 || q[i] > joints[i].max + 1e-9) return i;
  return -1;
}

std::vector<std::string> robot_preset_names() { return {"inchworm7"}; }

RobotModel robot_preset(const std::string& name) {
  if (name != "inchworm7")
    throw ParameterError("robot: unknown preset '" + name + "' (expected inchworm7)");
  // Symmetric 7-DOF biped inchworm (two grippers, roll-pitch-twist-elbow-twist-pitch-roll),
  // standard DH. Lengths: 0.15 m foot (gripper to first pitch axis), two 0.55 m limbs,
  // 0.15 m foot at the camera end; ~1.4 m span, enough to reach a 1.3 m roof from the floor.
  RobotModel r;
  r.name = "inchworm7";
  r.convention = DhConvention::Standard;
  auto J = [](const char* n, double a, double alpha_deg, double d, double lim_deg) {
    DhJoint j;
    j.name = n;
    j.a_m = a;
    j.alpha_rad = alpha_deg * kDeg;
    j.d_m = d;
    j.min = -lim_deg * kDeg;
    j.max = lim_deg * kDeg;
    return j;
  };
  r.joints = {J("foot_roll", 0, -90, 0.15, 180), J("hip_pitch", 0, 90, 0, 120),
              J("thigh_twist", 0, -90, 0.55, 180), J("knee_pitch", 0, 90, 0, 150),
              J("shank_twist", 0, -90, 0.55, 180), J("ankle_pitch", 0, 90, 0, 120),
              J("gripper_roll", 0, 0, 0.15, 180)};
  // Camera 6 cm beyond the flange, looking along the last link (camera z = flange z).
  r.tool_to_camera.translation() = Eigen::Vector3d(0, 0, 0.06);
  return r;
}

std::vector<double> robot_home(const RobotModel& robot) {
  std::vector<double> q(static_cast<std::size_t>(robot.dof()), 0.0);
  if (robot.name == "inchworm7" && robot.dof() == 7) q = {0, 0.5, 0, 1.2, 0, 0.6, 0};
  return q;
}

}  // namespace tunnelmap
