#include "core/mapping/mapping_notes.h"

#include <algorithm>
#include <cstdio>

#include "core/mapping/gravity_agreement.h"

namespace tunnelmap {

// A pose off by metres maps its view where it claims, as a stretch no one else saw: nothing
// checks it. Told only when other groups are checked (a walk nothing ties is reported as such).
std::vector<std::string> unchecked_pose_notes(const PoseRefinement& refinement,
                                              const std::vector<UncheckedPlate>& plates) {
  std::vector<std::string> lines;
  const std::vector<int> unchecked = frames_nothing_checks(refinement);
  for (const PoseCorrection& c : refinement.groups) {
    if (c.frames.empty() || !std::binary_search(unchecked.begin(), unchecked.end(), c.frames.front())) continue;
    std::string line = "pose " + std::to_string(c.group) + " (frames " + std::to_string(c.frames.front()) + "-" +
                       std::to_string(c.frames.back()) +
                       "): nothing it saw was seen from another pose, so nothing checks it; mapped where its pose "
                       "puts it";
    std::vector<std::string> stations;
    for (const UncheckedPlate& p : plates)
      if (std::find_first_of(p.frames.begin(), p.frames.end(), c.frames.begin(), c.frames.end()) != p.frames.end()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.3f", p.station_m);
        stations.push_back(text);
      }
    if (stations.size() == 1) line += ", but for the plate it saw at station " + stations[0] + " m, which is not mapped";
    if (stations.size() > 1) {
      line += ", but for the plates it saw at stations " + stations[0];
      for (std::size_t i = 1; i < stations.size(); ++i) line += (i + 1 == stations.size() ? " and " : ", ") + stations[i];
      line += " m, which are not mapped";
    }
    lines.push_back(line);
  }
  return lines;
}

namespace {

// "3", "3 and 4", "3, 4 and 9".
std::string listed(const std::vector<int>& v) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out += (i == 0 ? "" : i + 1 == v.size() ? " and " : ", ") + std::to_string(v[i]);
  return out;
}

}  // namespace

// Such views lose the plate's farthest pixels first, so they place it too near; a nearer view
// would place it.
std::vector<std::string> plates_beyond_range_notes(const std::vector<PlateBeyondRange>& plates) {
  std::vector<std::string> lines;
  for (const PlateBeyondRange& p : plates) {
    char station[32];
    std::snprintf(station, sizeof station, "%.3f", p.station_m);
    lines.push_back(std::string("the plate at about station ") + station + " m (" +
                    (p.frames.size() == 1 ? "frame " : "frames ") + listed(p.frames) +
                    ") was seen only near the end of the depth range, which places it too near, so it is not "
                    "mapped; a frame nearer to it would map it");
  }
  return lines;
}

std::vector<std::string> MappingNotes::all() const {
  std::vector<std::string> lines = unchecked_poses;
  lines.insert(lines.end(), plates_beyond_range.begin(), plates_beyond_range.end());
  if (!gravity.empty()) lines.push_back(gravity);
  return lines;
}

MappingNotes mapping_notes(const MappedSequence& mapped, const std::vector<std::optional<Eigen::Vector3d>>& gravity,
                           const Eigen::Vector3d& world_up, double gravity_deg) {
  MappingNotes notes;
  notes.unchecked_poses = unchecked_pose_notes(mapped.refinement, mapped.stations.girder.unchecked_plates);
  notes.plates_beyond_range = plates_beyond_range_notes(mapped.stations.girder.plates_beyond_range);
  if (mapped.refinement.ran)
    notes.gravity = gravity_noise_note(gravity_agreement(mapped.poses, gravity, world_up), gravity_deg);
  return notes;
}

}  // namespace tunnelmap
