#pragma once
// The result of pose refinement against the structure (core/mapping/structure_slam.h): per pose
// group the rigid correction of its odometry or forward-kinematics pose, the directions the
// structure constrained and those left to odometry (degenerate), and the refined pose of every
// frame. See docs/tunnel-map.md.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/solvers/correction_evidence.h"

namespace tunnelmap {

// The six directions of a correction, in the tunnel frame: rotations about the axis, the
// lateral (left) direction and up; translations along left, up and the axis.
enum PoseAxis { kRoll = 0, kPitch, kYaw, kLateral, kVertical, kAxial };
const char* pose_axis_name(int axis);  // "roll", "pitch", "yaw", "lateral", "vertical", "axial"

struct PoseCorrection {
  int group = 0;
  std::vector<int> frames;
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();  // refined = delta * forward kinematics
  double rotation_deg = 0.0;     // angle of the correction's rotation
  double translation_mm = 0.0;   // how far the correction moves the group's camera centre
  std::vector<std::string> constrained, degenerate;  // pose_axis_name()s
  int samples = 0;               // wall and transverse samples that took part
};

struct PoseRefinement {
  bool ran = false;              // false: no frame detected the tunnel (nothing to align with)
  std::vector<PoseCorrection> groups;
  std::vector<Eigen::Isometry3d> poses;  // per frame, refined
  int iterations = 0;
  // Whether the structure's disagreement with the given poses is beyond its noise; when it is
  // not, the given poses are kept and every correction is zero.
  CorrectionEvidence evidence;
  bool given_poses_kept = false;
  double ms = 0.0;                       // the estimate's time, every frame's share included
};

// The frames of the pose groups that share no wall or plate with any other (nothing constrained
// their correction), when other groups do share some: what they saw lies where their poses
// alone put it. Empty when the refinement did not run or no group was tied.
std::vector<int> frames_nothing_checks(const PoseRefinement& refinement);

}  // namespace tunnelmap
