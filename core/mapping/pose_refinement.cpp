#include "core/mapping/pose_refinement.h"

namespace tunnelmap {

const char* pose_axis_name(int axis) {
  static const char* names[] = {"roll", "pitch", "yaw", "lateral", "vertical", "axial"};
  return axis >= 0 && axis < 6 ? names[axis] : "?";
}

}  // namespace tunnelmap
