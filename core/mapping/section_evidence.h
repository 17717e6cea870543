#pragma once
// A section boundary that a pose error could have made is no boundary. Station sizes pooled
// over frames carry the frames' pose errors, and a run of stations measured from one view (a
// plate's rim, a far grazing wall, a biased frame) steps with that view. A frame's own sizes on
// both sides of a joint come from one pose, so the step between them is the girder's. A new
// section is kept only where single frames of at least `min_poses` pose groups each measure
// the step themselves (their own sizes on the two sides differ by more than the section
// change, in the direction of the sections' step); otherwise the two sections are one.
#include <vector>

#include "core/mapping/station_sections.h"

namespace tunnelmap {

// One frame's own size at one station (NaN where it did not measure that dimension).
struct FrameStationSize {
  int frame = 0;
  int station = 0;  // index into the profile split by split_sections
  double width_m = 0.0, height_m = 0.0;
};

// `pose_groups[frame]`: the frame's pose group (a frame past its end is a group of its own).
// `width_m`, `height_m`: the profile that was split (to recompute merged sections' medians).
SectionSplit keep_confirmed_joints(const SectionSplit& split, const std::vector<double>& width_m,
                                   const std::vector<double>& height_m, const std::vector<FrameStationSize>& views,
                                   const std::vector<int>& pose_groups, double change_m, int min_poses = 2);

}  // namespace tunnelmap
