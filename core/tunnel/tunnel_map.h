#pragma once
// TunnelMap: the fourth stage, the rectangular tunnel template fitted to the planes.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/util/stage_timer.h"

namespace tunnelmap {

enum class WallClass { Left = 0, Right = 1, Top = 2, Bottom = 3, Unassigned = 4 };
const char* wall_class_name(WallClass c);  // "left", "right", "top", "bottom", "unassigned"

enum class ZoneKind { Forbidden, Traversable };

// A rectangle lying on a wall: `corners` in order, in the frame the map is expressed in.
struct ZoneRect {
  ZoneKind kind = ZoneKind::Traversable;
  std::array<Eigen::Vector3d, 4> corners;
};

struct ZoneCluster {
  double offset_m = 0.0;  // position along the wall normal (wall plane: n.x + offset = 0)
  int planes = 0;
  int points = 0;
};

struct Wall {
  WallClass cls = WallClass::Unassigned;
  bool found = false;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, pointing into the tunnel
  double offset_m = 0.0;                               // plane: normal.dot(x) + offset_m = 0
  std::vector<ZoneCluster> clusters;                   // zone positions on this wall
  std::vector<ZoneRect> zones;                         // forbidden edge bands + middle plate
  std::array<Eigen::Vector3d, 4> boundary;             // wall rectangle over the visible extent
  // Gaussian statistics of the class's plane normals (added fields).
  int inlier_planes = 0;       // planes of this class kept by the histogram test
  int outlier_planes = 0;      // planes of this class rejected by the histogram test
  double normal_sd_deg = 0.0;  // RMS angle of the inlier normals about their mean
  double symmetric_step_m = 0.0;  // edge step borrowed from the opposite wall (0 = measured)
};

struct TunnelMap {
  bool detected = false;
  std::string status = "not_run";  // "ok", "too_few_planes", "no_parallel_pair", ...
  std::string reason;              // human-readable detail for the status
  double width_m = 0.0;            // left-right distance
  double height_m = 0.0;           // bottom-top distance
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();  // on the tunnel centre line
  Eigen::Vector3d axis_dir = Eigen::Vector3d::UnitZ();   // unit, along the tunnel
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();        // unit, towards the roof
  double extent_min_m = 0.0;       // visible axial extent, along axis_dir from axis_point
  double extent_max_m = 0.0;
  std::array<Wall, 4> walls;       // indexed by WallClass (Left..Bottom)
  std::vector<WallClass> plane_classes;  // per PlaneSegment (same order), after outliers
  std::vector<bool> plane_outlier;       // per PlaneSegment: rejected by the histogram test
  std::vector<WallClass> plane_candidate_classes;  // per PlaneSegment: class before outliers
  StageTimings timings_ms;

  const Wall& wall(WallClass c) const { return walls[static_cast<int>(c)]; }
  Wall& wall(WallClass c) { return walls[static_cast<int>(c)]; }
};

}  // namespace tunnelmap
