#include "core/mapping/mapping_notes.h"

#include <algorithm>

#include "core/mapping/gravity_agreement.h"

namespace tunnelmap {

namespace {

// A pose off by metres maps its view where it claims, as a stretch no one else saw: nothing
// checks it. Told only when other groups are checked (a walk nothing ties is reported as such).
std::vector<std::string> unchecked_pose_lines(const PoseRefinement& refinement) {
  std::vector<std::string> lines;
  if (!refinement.ran) return lines;
  const bool any_tied = std::any_of(refinement.groups.begin(), refinement.groups.end(),
                                    [](const PoseCorrection& c) { return !c.constrained.empty(); });
  if (!any_tied) return lines;
  for (const PoseCorrection& c : refinement.groups)
    if (c.constrained.empty() && !c.frames.empty())
      lines.push_back("pose " + std::to_string(c.group) + " (frames " + std::to_string(c.frames.front()) + "-" +
                      std::to_string(c.frames.back()) +
                      "): nothing it saw was seen from another pose, so nothing checks it; mapped where its pose "
                      "puts it");
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
  notes.unchecked_poses = unchecked_pose_lines(mapped.refinement);
  if (mapped.refinement.ran)
    notes.gravity = gravity_noise_note(gravity_agreement(mapped.poses, gravity, world_up), gravity_deg);
  return notes;
}

}  // namespace tunnelmap
