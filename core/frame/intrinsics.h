#pragma once
// Pinhole intrinsics of the depth camera (pixels). Image x to the right, y down, z forward.
#include <Eigen/Core>

namespace tunnelmap {

struct Intrinsics {
  double fx = 570.3;
  double fy = 570.3;
  double cx = 319.5;
  double cy = 239.5;
  int width = 640;
  int height = 480;

  // Back-projects pixel (u, v) at depth z (metres) into the camera frame.
  Eigen::Vector3f backproject(float u, float v, float z) const {
    return {static_cast<float>((u - cx) * z / fx), static_cast<float>((v - cy) * z / fy), z};
  }
  // Unit-less ray direction (z = 1) through pixel (u, v).
  Eigen::Vector3d ray(double u, double v) const { return {(u - cx) / fx, (v - cy) / fy, 1.0}; }

  // PrimeSense / Structure Sensor class VGA depth camera.
  static Intrinsics primesense_vga() { return {}; }
};

}  // namespace tunnelmap
