#pragma once
// RobotModel: a serial manipulator described by a Denavit-Hartenberg table, and its forward
// kinematics 0T_s(q): world <- base <- joints 1..n <- flange <- camera (the paper's sensor pose).
// Pure Eigen. JSON form and conventions: docs/kinematics.md.
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tunnelmap {

// Standard (distal, Craig's "classic"): A_i = Rz(theta) Tz(d) Tx(a) Rx(alpha).
// Modified (proximal, Craig 1989):      A_i = Rx(alpha) Tx(a) Rz(theta) Tz(d).
enum class DhConvention { Standard, Modified };
enum class JointType { Revolute, Prismatic };

struct DhJoint {
  std::string name;
  JointType type = JointType::Revolute;
  double a_m = 0.0;
  double alpha_rad = 0.0;
  double d_m = 0.0;
  double theta_rad = 0.0;  // revolute: offset added to q; prismatic: the fixed angle
  double min = -M_PI, max = M_PI;  // joint limits: rad (revolute) or m (prismatic, d = d_m + q)
};

struct RobotModel {
  std::string name;
  DhConvention convention = DhConvention::Standard;
  std::vector<DhJoint> joints;
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();            // world <- base (frame 0)
  Eigen::Isometry3d tool_to_camera = Eigen::Isometry3d::Identity();  // flange <- camera

  int dof() const { return static_cast<int>(joints.size()); }
  // One link transform A_i(q_i) (frame i-1 <- frame i), in the model's convention.
  Eigen::Isometry3d link_transform(int i, double q) const;
  // Frames 0..n in the world (0 = base, n = flange); q.size() must equal dof().
  std::vector<Eigen::Isometry3d> joint_frames(const std::vector<double>& q) const;
  Eigen::Isometry3d flange_pose(const std::vector<double>& q) const;  // world <- flange
  Eigen::Isometry3d camera_pose(const std::vector<double>& q) const;  // world <- camera
  // Index of the first joint outside its limits (tolerance 1e-9), -1 when all are inside.
  int first_joint_out_of_limits(const std::vector<double>& q) const;
};

// Built-in robots. "inchworm7": the 7-DOF biped inchworm climbing robot (docs/kinematics.md).
// Throws ParameterError for an unknown name.
RobotModel robot_preset(const std::string& name);
std::vector<std::string> robot_preset_names();

// A home configuration for a preset (used as the IK seed by the simulator).
std::vector<double> robot_home(const RobotModel& robot);

}  // namespace tunnelmap
