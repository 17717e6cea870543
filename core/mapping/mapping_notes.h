#pragma once
// What a user should know about a mapped sequence that no field of the map says outright: pose
// groups that nothing checks, and an IMU noisier than the estimate weighs it. Every front end
// shows these same lines (the CLI prints them, the GUI lists them beside the map).
#include <string>
#include <vector>

#include "core/mapping/posed_sequence.h"

namespace tunnelmap {

struct MappingNotes {
  // One line per pose group that shares no wall or plate with any other while others do:
  // "pose 3 (frames 6-7): nothing it saw was seen from another pose, so nothing checks it; …".
  std::vector<std::string> unchecked_poses;
  std::string gravity;  // gravity_noise_note(); empty when the IMU agrees, or there is none
  // One line per plate only views near the end of the depth range saw, which the map leaves out.
  std::vector<std::string> plates_beyond_range;

  std::vector<std::string> all() const;
};

// One line per pose group that nothing checks while others are checked, naming the plates only
// such poses saw (which the map leaves out); `map` notes these, `fuse` prints them.
std::vector<std::string> unchecked_pose_notes(const PoseRefinement& refinement,
                                              const std::vector<UncheckedPlate>& plates);

// One line per plate only views near the end of the depth range saw: "the plate at station
// 41.210 m (frames 12 and 13) was seen only near the end of the depth range, …".
std::vector<std::string> plates_beyond_range_notes(const std::vector<PlateBeyondRange>& plates);

// `gravity`: each frame's IMU gravity (camera frame), as the dataset gives it.
MappingNotes mapping_notes(const MappedSequence& mapped, const std::vector<std::optional<Eigen::Vector3d>>& gravity,
                           const Eigen::Vector3d& world_up, double gravity_deg);

}  // namespace tunnelmap
