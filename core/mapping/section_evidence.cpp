#include "core/mapping/section_evidence.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/util/median.h"

namespace tunnelmap {

namespace {

struct Profile {
  const std::vector<double>& width_m;
  const std::vector<double>& height_m;
};

// A frame's own sizes over one section's stations.
struct Sides {
  std::vector<double> w[2], h[2];
};

using FrameSides = std::map<int, Sides>;

FrameSides sides_by_frame(const SectionRun& a, const SectionRun& b, const std::vector<FrameStationSize>& views) {
  FrameSides by_frame;
  for (const FrameStationSize& v : views) {
    const int side = v.station >= a.first && v.station <= a.last ? 0 : v.station >= b.first && v.station <= b.last ? 1 : -1;
    if (side < 0) continue;
    Sides& s = by_frame[v.frame];
    s.w[side].push_back(v.width_m);
    s.h[side].push_back(v.height_m);
  }
  return by_frame;
}

// Nearer the sections' step than no step, and in its direction: a far view blurs the stations
// next to the joint, so its own step may fall short of the whole one.
bool steps(const std::vector<double>& before, const std::vector<double>& after, double section_step, double change) {
  const double a = median_of_measured(before), b = median_of_measured(after);
  if (std::isnan(a) || std::isnan(b) || std::isnan(section_step)) return false;
  return std::abs(b - a) > 0.5 * std::max(std::abs(section_step), change) && (b - a) * section_step > 0;
}

int pose_of(int frame, const std::vector<int>& pose_groups) {
  const bool grouped = frame >= 0 && frame < static_cast<int>(pose_groups.size());
  return grouped ? pose_groups[static_cast<std::size_t>(frame)] : -1 - frame;
}

// Pose groups whose frames measure, each on its own, the step from section `a` to section `b`.
std::set<int> poses_seeing_step(const SectionRun& a, const SectionRun& b, const FrameSides& frames,
                                const JointEvidence& e) {
  std::set<int> poses;
  for (const auto& [frame, s] : frames) {
    if (!steps(s.w[0], s.w[1], b.width_m - a.width_m, e.change_m) &&
        !steps(s.h[0], s.h[1], b.height_m - a.height_m, e.change_m))
      continue;
    poses.insert(pose_of(frame, e.pose_groups));
  }
  return poses;
}

bool measured(const std::vector<double>& v) { return !std::isnan(median_of_measured(v)); }

// The dimension that steps: 0 width, 1 height (the larger step).
int stepping_dimension(const SectionRun& a, const SectionRun& b) {
  const double dw = std::abs(b.width_m - a.width_m), dh = std::abs(b.height_m - a.height_m);
  return !(dh > dw) ? 0 : 1;
}

// Where a joint no frame saw whole may lie: the stations after the last whose size is nearer
// `a`'s and before the first nearer `b`'s (the profile: a frame's own sizes, else pooled
// positions). It is hidden when a plate stands within reach of that stretch (past the plate
// the robot's first views look over the stretch behind it) and no frame that measured the
// stepping dimension on both sides saw it stay.
struct HiddenStretch {
  int last_a = 0, first_b = 0;
};

std::optional<HiddenStretch> hidden_by_plate(const SectionRun& a, const SectionRun& b, const FrameSides& frames,
                                             const Profile& profile, const JointEvidence& e) {
  const int dim = stepping_dimension(a, b);
  const std::vector<double>& size = dim == 0 ? profile.width_m : profile.height_m;
  const double size_a = dim == 0 ? a.width_m : a.height_m, size_b = dim == 0 ? b.width_m : b.height_m;
  const auto at = [&](int k) { return size[static_cast<std::size_t>(k)]; };
  const auto nearer_a = [&](int k) { return std::abs(at(k) - size_a) < std::abs(at(k) - size_b); };
  int last_a = a.first - 1, first_b = b.last + 1;
  for (int k = a.first; k <= a.last; ++k)
    if (!std::isnan(at(k)) && nearer_a(k)) last_a = k;
  for (int k = b.last; k >= b.first; --k)
    if (!std::isnan(at(k)) && !nearer_a(k)) first_b = k;
  const double step = size_b - size_a;
  for (const auto& [frame, s] : frames) {
    const std::vector<double>& before = dim == 0 ? s.w[0] : s.h[0];
    const std::vector<double>& after = dim == 0 ? s.w[1] : s.h[1];
    if (measured(before) && measured(after) && !steps(before, after, step, e.change_m)) return std::nullopt;
  }
  for (int p : e.plate_stations)
    if (p >= last_a - e.plate_reach && p <= first_b + e.plate_reach && p >= a.first && p < b.last)
      return HiddenStretch{last_a, first_b};
  return std::nullopt;
}

// Pose groups whose frames' own sizes on one side are nearer that side's size than the other's.
bool each_side_measured(const SectionRun& a, const SectionRun& b, const FrameSides& frames, const JointEvidence& e) {
  const int dim = stepping_dimension(a, b);
  const double size[2] = {dim == 0 ? a.width_m : a.height_m, dim == 0 ? b.width_m : b.height_m};
  std::set<int> poses[2];
  for (const auto& [frame, s] : frames)
    for (int side = 0; side < 2; ++side) {
      const double own = median_of_measured(dim == 0 ? s.w[side] : s.h[side]);
      if (std::abs(own - size[side]) < std::abs(own - size[1 - side])) poses[side].insert(pose_of(frame, e.pose_groups));
    }
  return static_cast<int>(poses[0].size()) >= e.min_poses && static_cast<int>(poses[1].size()) >= e.min_poses;
}

SectionRun with_medians(int first, int last, const SectionSplit& split, const std::vector<double>& w,
                        const std::vector<double>& h) {
  std::vector<double> sw, sh;
  for (int k = first; k <= last; ++k) {
    if (split.outlier[static_cast<std::size_t>(k)]) continue;
    sw.push_back(w[static_cast<std::size_t>(k)]);
    sh.push_back(h[static_cast<std::size_t>(k)]);
  }
  return {first, last, median_of_measured(sw), median_of_measured(sh)};
}

bool differ(const SectionRun& a, const SectionRun& b, double change) {
  return std::abs(b.width_m - a.width_m) > change || std::abs(b.height_m - a.height_m) > change;
}

}  // namespace

SectionSplit keep_confirmed_joints(const SectionSplit& split, const std::vector<double>& width_m,
                                   const std::vector<double>& height_m, const JointEvidence& e) {
  SectionSplit out;
  out.outlier = split.outlier;
  for (const SectionRun& run : split.sections) {
    if (out.sections.empty()) {
      out.sections.push_back(run);
      continue;
    }
    SectionRun& last = out.sections.back();
    const FrameSides frames = sides_by_frame(last, run, e.views);
    if (static_cast<int>(poses_seeing_step(last, run, frames, e).size()) >= e.min_poses) {
      out.sections.push_back(run);
      continue;
    }
    const std::optional<HiddenStretch> hidden = hidden_by_plate(last, run, frames, Profile{width_m, height_m}, e);
    if (hidden && each_side_measured(last, run, frames, e)) {
      // Nothing measured where in the stretch the step is: the joint goes to its middle, at
      // most half the stretch from the truth. A step that was a short biased run next to the
      // plate is gone once the sides are whole.
      const int joint = std::clamp((hidden->last_a + hidden->first_b + 1) / 2, last.first + 1, run.last);
      const SectionRun before = with_medians(last.first, joint - 1, out, width_m, height_m);
      SectionRun after = with_medians(joint, run.last, out, width_m, height_m);
      after.unseen_joint_stations = hidden->first_b - hidden->last_a - 1;
      if (differ(before, after, e.change_m)) {
        last = before;
        out.sections.push_back(after);
        continue;
      }
    }
    last = with_medians(last.first, run.last, out, width_m, height_m);
  }
  // Merging may leave neighbours of one size (a short biased run kept at a plate, then the run
  // after it merged back): they are one section.
  SectionSplit merged;
  merged.outlier = out.outlier;
  for (const SectionRun& run : out.sections) {
    if (!merged.sections.empty() && !differ(merged.sections.back(), run, e.change_m)) {
      SectionRun& last = merged.sections.back();
      const int unseen = last.unseen_joint_stations;
      last = with_medians(last.first, run.last, out, width_m, height_m);
      last.unseen_joint_stations = unseen;
    } else
      merged.sections.push_back(run);
  }
  return merged;
}

}  // namespace tunnelmap
