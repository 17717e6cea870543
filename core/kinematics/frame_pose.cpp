#include "core/kinematics/frame_pose.h"

#include <cmath>

#include "core/kinematics/robot_json.h"
#include "core/util/error.h"

namespace tunnelmap {

const char* pose_source_name(PoseSource s) {
  switch (s) {
    case PoseSource::None: return "none";
    case PoseSource::Explicit: return "pose";
    case PoseSource::Kinematics: return "joints";
  }
  return "?";
}

std::optional<RobotModel> dataset_robot(const Dataset& dataset) {
  if (dataset.robot.is_null()) return std::nullopt;
  return robot_from_json(dataset.robot, dataset.json_path);
}

ResolvedPose resolve_frame_pose(const Dataset& dataset, std::size_t i, bool prefer_joints) {
  const DatasetFrameRef& f = dataset.frames.at(i);
  const std::string where = "frames[" + std::to_string(i) + "]";
  ResolvedPose r;
  const bool use_fk = !f.joints.empty() && (prefer_joints || !f.pose);
  if (!use_fk) {
    if (f.pose) r = {f.pose, PoseSource::Explicit};
    return r;
  }
  std::optional<RobotModel> robot = dataset_robot(dataset);
  if (!robot) {
    if (f.pose) return {f.pose, PoseSource::Explicit};
    throw InputError(dataset.json_path, where + " has joints but the dataset has no \"robot\"");
  }
  if (static_cast<int>(f.joints.size()) != robot->dof())
    throw InputError(dataset.json_path, where + ".joints has " + std::to_string(f.joints.size()) +
                                            " values; the robot has " +
                                            std::to_string(robot->dof()) + " joints");
  const int bad = robot->first_joint_out_of_limits(f.joints);
  if (bad >= 0)
    throw InputError(dataset.json_path, where + ".joints[" + std::to_string(bad) + "] = " +
                                            std::to_string(f.joints[bad]) +
                                            " is outside the limits of joint '" +
                                            robot->joints[bad].name + "'");
  if (f.raw.is_object() && f.raw.contains("robot_base"))
    robot->base = isometry_from_json(f.raw["robot_base"], dataset.json_path, where + ".robot_base");
  r.pose = robot->camera_pose(f.joints);
  r.source = PoseSource::Kinematics;
  return r;
}

}  // namespace tunnelmap
