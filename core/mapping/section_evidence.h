#pragma once
// A section boundary that a pose error could have made is no boundary. Station sizes pooled
// over frames carry the frames' pose errors, and a run of stations measured from one view (a
// plate's rim, a far grazing wall, a biased frame) steps with that view. A frame's own sizes on
// both sides of a joint come from one pose, so the step between them is the girder's. A new
// section is kept only where single frames of at least `min_poses` pose groups each measure
// the step themselves (their own sizes on the two sides differ, in the direction of the
// sections' step, by more than half of it), or where one pose group's frames see the step and
// the frames of `min_poses` pose groups on each side measure their side's size (below) and the
// frames of fewer than `min_poses` pose groups see the size stay across (the station next to
// the joint on each side left out: it lies on either side within the poses' error along the
// girder); otherwise the two sections are one.
//
// A plate across the girder hides each side of it from the other, so a joint at a plate is
// never seen whole by one frame. There the evidence is the frames' own sizes on each side: at
// least `min_poses` pose groups on each side measure their side's size (nearer it than the
// other side's), and the frames that see the stepping dimension on both sides (through the
// plate's manhole) and see it stay belong to fewer than `min_poses` pose groups. The joint
// then goes to the middle of the stretch where no station tells its side
// (core/mapping/joint_stretch.h), as it does where views saw both sides but nothing measured
// the stations between them.
#include <array>
#include <vector>

#include "core/mapping/station_sections.h"

namespace tunnelmap {

// One frame's own size at one station (NaN where it did not measure that dimension).
struct FrameStationSize {
  int frame = 0;
  int station = 0;  // index into the profile split by split_sections
  double width_m = 0.0, height_m = 0.0;
};

struct JointEvidence {
  std::vector<FrameStationSize> views;
  std::vector<int> pose_groups;     // per frame; a frame past its end is a group of its own
  std::vector<int> plate_stations;  // plates across the girder, as profile indices, ascending
  // Pooled wall positions per profile station (left, right, bottom, top; NaN where unseen).
  // Where no frame measured the stepping dimension, the wall that carries the step alone
  // still tells on which side of the joint a station lies.
  std::vector<std::array<double, 4>> wall_m;
  double change_m = 0.012;          // the section change (map.section_change_mm)
  int min_poses = 2;
  int plate_reach = 1;  // stations: a plate this far outside the stretch the step lies in still hides it
};

// `width_m`, `height_m`: the profile that was split (to recompute merged sections' medians).
SectionSplit keep_confirmed_joints(const SectionSplit& split, const std::vector<double>& width_m,
                                   const std::vector<double>& height_m, const JointEvidence& evidence);

}  // namespace tunnelmap
