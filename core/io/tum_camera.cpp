#include "core/io/tum_camera.h"

namespace tunnelmap {

std::optional<TumCamera> tum_camera_from_folder_name(const std::string& folder_name) {
  // vision.in.tum.de/data/datasets/rgbd-dataset/file_formats (calibration of the colour camera,
  // to which the depth images are registered).
  static const struct {
    const char* name;
    double fx, fy, cx, cy;
  } cameras[] = {{"freiburg1", 517.3, 516.5, 318.6, 255.3},
                 {"freiburg2", 520.9, 521.0, 325.1, 249.7},
                 {"freiburg3", 535.4, 539.2, 320.1, 247.6}};
  for (const auto& c : cameras) {
    if (folder_name.find(c.name) == std::string::npos) continue;
    TumCamera cam;
    cam.name = c.name;
    cam.intrinsics.fx = c.fx;
    cam.intrinsics.fy = c.fy;
    cam.intrinsics.cx = c.cx;
    cam.intrinsics.cy = c.cy;
    cam.intrinsics.width = 640;
    cam.intrinsics.height = 480;
    return cam;
  }
  return std::nullopt;
}

}  // namespace tunnelmap
