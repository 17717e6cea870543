#pragma once
// Camera pose of a dataset frame, by precedence: the frame's explicit "pose"; else forward
// kinematics of its "joints" with the dataset's "robot" (a frame's "robot_base" replaces
// robot.base: the inchworm has stepped); else none.
#include <optional>
#include <string>

#include "core/io/dataset.h"
#include "core/kinematics/robot_model.h"

namespace tunnelmap {

enum class PoseSource { None, Explicit, Kinematics };
const char* pose_source_name(PoseSource s);  // "none", "pose", "joints"

struct ResolvedPose {
  std::optional<Eigen::Isometry3d> pose;  // camera-to-world
  PoseSource source = PoseSource::None;
};

// `prefer_joints`: use FK even when the frame has an explicit pose (to study the arm's error).
// InputError naming dataset.json and the frame when joints do not fit the robot (count,
// limits) or a frame has joints but the dataset has no robot.
ResolvedPose resolve_frame_pose(const Dataset& dataset, std::size_t frame_index,
                                bool prefer_joints = false);

// The dataset's robot, parsed (nullopt when the dataset has none).
std::optional<RobotModel> dataset_robot(const Dataset& dataset);

}  // namespace tunnelmap
