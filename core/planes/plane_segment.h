#pragma once
// PlaneSegments: the third stage, bounded planes found by PG&C (or a baseline method).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/util/stage_timer.h"

namespace tunnelmap {

struct PlaneSegment {
  int id = 0;                    // 1-based; equals the value in the label image
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();       // unit, facing the camera (camera frame)
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();     // mean point (metres, camera frame)
  Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero();  // eq. 3 running mean of point normals, normalised
  double offset_m = 0.0;         // plane: normal.dot(x) + offset_m = 0
  int points = 0;
  double area_m2 = 0.0;          // sum of the pixel footprints on the plane
  double rms_m = 0.0;            // RMS point-to-plane distance
  std::vector<Eigen::Vector3d> contour;  // outer boundary polygon on the plane (camera frame)
  int bbox_u0 = 0, bbox_v0 = 0, bbox_u1 = 0, bbox_v1 = 0;  // inclusive pixel bounding box
  bool edge_on = false;  // found by the edge-on pass of coarse-to-fine growing (seen nearly edge-on)

  double distance(const Eigen::Vector3d& x) const { return normal.dot(x) + offset_m; }
};

struct PlaneSegments {
  int width = 0;
  int height = 0;
  std::vector<PlaneSegment> planes;
  std::vector<std::int32_t> labels;  // width*height; 0 = no plane, else PlaneSegment::id
  StageTimings timings_ms;
};

}  // namespace tunnelmap
