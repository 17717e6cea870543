#include "core/mapping/mapping_notes.h"

#include <algorithm>
#include <cstdio>

#include "core/mapping/gravity_agreement.h"

namespace tunnelmap {

namespace {

// A pose off by metres maps its view where it claims, as a stretch no one else saw: nothing
// checks it. Told only when other groups are checked (a walk nothing ties is reported as such).
std::vector<std::string> unchecked_pose_lines(const PoseRefinement& refinement,
                                              const std::vector<UncheckedPlate>& plates) {
  std::vector<std::string> lines;
  const std::vector<int> unchecked = frames_nothing_checks(refinement);
  for (const PoseCorrection& c : refinement.groups) {
    if (c.frames.empty() || !std::binary_search(unchecked.begin(), unchecked.end(), c.frames.front())) continue;
    std::string line = "pose " + std::to_string(c.group) + " (frames " + std::to_string(c.frames.front()) + "-" +
                       std::to_string(c.frames.back()) +
                       "): nothing it saw was seen from another pose, so nothing checks it; mapped where its pose "
                       "puts it";
    for (const UncheckedPlate& p : plates)
      if (std::find_first_of(p.frames.begin(), p.frames.end(), c.frames.begin(), c.frames.end()) != p.frames.end()) {
        char text[96];
        std::snprintf(text, sizeof text, ", but for the plate it saw at station %.3f m, which is not mapped", p.station_m);
        line += text;
      }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace

std::vector<std::string> MappingNotes::all() const {
  std::vector<std::string> lines = unchecked_poses;
  if (!gravity.empty()) lines.push_back(gravity);
  return lines;
}

MappingNotes mapping_notes(const MappedSequence& mapped, const std::vector<std::optional<Eigen::Vector3d>>& gravity,
                           const Eigen::Vector3d& world_up, double gravity_deg) {
  MappingNotes notes;
  notes.unchecked_poses = unchecked_pose_lines(mapped.refinement, mapped.stations.girder.unchecked_plates);
  if (mapped.refinement.ran)
    notes.gravity = gravity_noise_note(gravity_agreement(mapped.poses, gravity, world_up), gravity_deg);
  return notes;
}

}  // namespace tunnelmap
