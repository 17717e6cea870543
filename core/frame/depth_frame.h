#pragma once
// DepthFrame: one depth image as it came from a sensor or file, the first stage of the
// pipeline. Depth is kept in the file's units (`depth_units_per_m`, e.g. 1000 for millimetre
// PNGs, 1 for metres) so that nothing is lost in conversion; 0 or non-finite = no measurement.
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

struct DepthFrame {
  int width = 0;
  int height = 0;
  std::vector<float> depth;          // row-major, width*height, in file units
  double depth_units_per_m = 1000.0; // divide `depth` by this for metres
  std::vector<std::uint8_t> rgb;     // optional registered colour, RGB8 row-major (empty if none)
  Intrinsics intrinsics;
  std::optional<Eigen::Isometry3d> pose;  // camera-to-world, when known
  std::vector<double> joints;             // arm joint vector, when known
  // The direction things fall, camera frame, unit: an IMU's gravity at the frame (an
  // accelerometer at rest reads its opposite), when known.
  std::optional<Eigen::Vector3d> gravity;
  double timestamp_s = 0.0;
  std::string source;                     // file or stream this frame came from (for messages)

  // An all-invalid frame of the intrinsics' size, in millimetres (what sensors and the
  // simulator produce before filling in depth).
  static DepthFrame blank_mm(const Intrinsics& K) {
    DepthFrame f;
    f.width = K.width;
    f.height = K.height;
    f.intrinsics = K;
    f.depth_units_per_m = 1000.0;
    f.depth.assign(static_cast<std::size_t>(K.width) * K.height, 0.0f);
    return f;
  }

  bool empty() const { return width <= 0 || height <= 0 || depth.empty(); }
  bool has_rgb() const { return rgb.size() == static_cast<std::size_t>(width) * height * 3; }
  float depth_m(int u, int v) const {
    const float d = depth[static_cast<std::size_t>(v) * width + u];
    return d / static_cast<float>(depth_units_per_m);
  }
};

}  // namespace tunnelmap
