#pragma once
// Pose refinement against the tunnel map: the arm sags, so forward kinematics puts each pose
// group's camera a little off. Each group's camera pose gets the rigid correction that best lays
// the wall points it measured onto the map built from all groups (walls along the tunnel,
// transverse faces such as a manhole plate or the step between two sections across it); the map
// is rebuilt from the corrected poses and the two are iterated until they agree. Only the
// directions the seen planes constrain are corrected: walls fix the rotation and the two
// transverse translations, a transverse face the position along the axis; a direction nothing
// constrains keeps its forward-kinematics value and is reported as degenerate. See
// docs/fusion.md.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/mapping/frame_walls.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct PoseRefinementOptions {
  int max_iterations = 10;
  double station_step_m = 0.10;  // along-axis bins of the map the walls are aligned with
  double huber_m = 0.010;        // residuals beyond this weigh less (robust to clutter)
  double gross_m = 0.10;         // residuals beyond this are not the same surface
  double transverse_gap_m = 0.10;  // transverse faces closer than this along the axis are one
  double max_transverse_depth_m = 2.5;  // farther faces are quantised in depth too coarsely
  // A direction whose information is below this fraction of the strongest is degenerate.
  double degenerate_ratio = 1e-4;
  double converged_deg = 0.002, converged_m = 0.0002;
};

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
  double ms = 0.0;
};

// `maps[i]`, `walls[i]`: frame i's detection (camera frame) and its wall samples;
// `poses[i]`: its forward-kinematics (or explicit) camera-to-world pose; `groups[i]`: its pose
// group (consecutive frames of one arm pose share one correction).
PoseRefinement refine_poses(const std::vector<TunnelMap>& maps,
                            const std::vector<FrameWalls>& walls,
                            const std::vector<Eigen::Isometry3d>& poses,
                            const std::vector<int>& groups,
                            const PoseRefinementOptions& options = PoseRefinementOptions());

}  // namespace tunnelmap
