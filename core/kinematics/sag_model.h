#pragma once
// Link sag: the real arm droops under gravity, so the true camera pose differs from the
// forward kinematics 0T_s(q). Model (docs/kinematics.md): everything beyond the shoulder
// (frame `pivot_frame`) turns down about the horizontal axis perpendicular to the horizontal
// reach, by an angle proportional to that reach: theta = k * |reach_h|. The camera thus drops
// by about k * |reach_h| * |reach| and tilts nose-down by theta: the error grows with reach.
#include <Eigen/Geometry>
#include <vector>

#include "core/kinematics/robot_model.h"

namespace tunnelmap {

struct SagModel {
  double deg_per_m = 0.0;  // k; 0 = rigid arm
  int pivot_frame = 1;     // joint frame the links hinge about (1 = the hip pitch axis)
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // world up (gravity opposite)
};

// True camera pose (world <- camera) of `robot` at `q` under `sag`.
Eigen::Isometry3d sagged_camera_pose(const RobotModel& robot, const std::vector<double>& q,
                                     const SagModel& sag);

}  // namespace tunnelmap
