#pragma once
// OrganizedCloud: per-pixel 3D points (camera frame, metres) and unit normals, the second
// stage. Invalid pixels hold NaN points / NaN normals. Normals face the camera (n.p < 0).
#include <Eigen/Core>
#include <vector>

#include "core/frame/intrinsics.h"
#include "core/util/stage_timer.h"

namespace tunnelmap {

struct OrganizedCloud {
  int width = 0;
  int height = 0;
  Intrinsics intrinsics;
  std::vector<Eigen::Vector3f> points;   // width*height, NaN where invalid
  std::vector<Eigen::Vector3f> normals;  // width*height, NaN where no normal
  StageTimings timings_ms;

  std::size_t index(int u, int v) const { return static_cast<std::size_t>(v) * width + u; }
  static bool valid(const Eigen::Vector3f& p) { return p.x() == p.x(); }  // not NaN
};

}  // namespace tunnelmap
