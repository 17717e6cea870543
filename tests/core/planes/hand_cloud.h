#pragma once
// Organised clouds built pixel by pixel for the plane-growing unit tests: every point and normal
// is chosen by the test, so the right regions and counts can be worked out by hand.
#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "core/frame/organized_cloud.h"

namespace tunnelmap::testing {

inline Eigen::Vector3f no_normal() {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  return {nan, nan, nan};
}

// A `w` x `h` cloud with the default VGA focal length; `fill(u, v, point, normal)` sets each
// pixel (leave the normal NaN for a pixel that can never join a plane).
template <class Fill>
OrganizedCloud hand_cloud(int w, int h, Fill fill) {
  OrganizedCloud c;
  c.width = w, c.height = h;
  c.intrinsics.width = w, c.intrinsics.height = h;
  c.points.assign(static_cast<std::size_t>(w) * h, no_normal());
  c.normals.assign(c.points.size(), no_normal());
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) fill(u, v, c.points[c.index(u, v)], c.normals[c.index(u, v)]);
  return c;
}

// Unit normal `n` turned by `deg` degrees about the camera's y axis.
inline Eigen::Vector3f tilted(const Eigen::Vector3f& n, double deg) {
  const float a = static_cast<float>(deg * M_PI / 180.0);
  return Eigen::Vector3f(std::cos(a) * n.x() + std::sin(a) * n.z(), n.y(),
                         -std::sin(a) * n.x() + std::cos(a) * n.z());
}

}  // namespace tunnelmap::testing
