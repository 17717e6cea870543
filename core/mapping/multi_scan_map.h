#pragma once
// Multi-scan tunnel map: per-frame TunnelMaps (camera frame) are brought into the world frame
// through their camera poses and merged along the tunnel axis into one map. Frames are grouped
// into arm poses; a pose where no frame found the tunnel (e.g. too few planes) is marked
// "move and rescan", as the paper's robot does.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct ScanInput {
  TunnelMap map;                       // as detected, in the camera frame
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();
  int frame_index = 0;
};

struct PoseGroupStatus {
  int group = 0;
  std::vector<int> frames;             // frame indices in this pose
  int detected_frames = 0;
  bool rescan = false;                 // no frame of this pose found the tunnel
  std::string status;                  // "ok" or the most common failure status
  std::string message;                 // "ok" or "move and rescan: <reason>"
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();  // the pose's first frame
};

struct MultiScanMap {
  TunnelMap map;                       // world frame; per-plane arrays empty
  std::vector<PoseGroupStatus> poses;
  int frames_merged = 0;               // detected frames that went into the map
  double width_spread_m = 0.0;         // max - min of the merged frames' widths
  double height_spread_m = 0.0;
};

// The same map expressed through `T` (points, directions, plane offsets, zones).
TunnelMap transform_map(const TunnelMap& map, const Eigen::Isometry3d& T);

// Consecutive frames whose camera moved less than `max_move_m` and `max_turn_deg` from the
// group's first frame share a group id (0, 1, ...).
std::vector<int> group_poses(const std::vector<Eigen::Isometry3d>& poses, double max_move_m,
                             double max_turn_deg = 5.0);

// Merges the detected maps: axis and up averaged, width/height the medians, walls rebuilt at
// +-width/2 and +-height/2 of the mean centre line, zones of each wall clustered across the
// wall (`zone_gap_m` apart) and continued over the union of the frames' axial extents.
// `groups[i]` is the pose group of scans[i]. status "no_detection" when no frame was detected.
MultiScanMap merge_scans(const std::vector<ScanInput>& scans, const std::vector<int>& groups,
                         double zone_gap_m = 0.010);

}  // namespace tunnelmap
