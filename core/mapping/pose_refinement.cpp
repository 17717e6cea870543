#include "core/mapping/pose_refinement.h"

#include <algorithm>

namespace tunnelmap {

const char* pose_axis_name(int axis) {
  static const char* names[] = {"roll", "pitch", "yaw", "lateral", "vertical", "axial"};
  return axis >= 0 && axis < 6 ? names[axis] : "?";
}

std::vector<int> frames_nothing_checks(const PoseRefinement& refinement) {
  std::vector<int> frames;
  if (!refinement.ran) return frames;
  const bool any_tied = std::any_of(refinement.groups.begin(), refinement.groups.end(),
                                    [](const PoseCorrection& c) { return !c.constrained.empty(); });
  if (!any_tied) return frames;
  for (const PoseCorrection& c : refinement.groups)
    if (c.constrained.empty()) frames.insert(frames.end(), c.frames.begin(), c.frames.end());
  std::sort(frames.begin(), frames.end());
  return frames;
}

}  // namespace tunnelmap
