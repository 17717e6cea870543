#include "core/mapping/section_evidence.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/mapping/joint_stretch.h"
#include "core/util/median.h"

namespace tunnelmap {

namespace {

// A frame's own sizes over one section's stations.
struct Sides {
  std::vector<double> w[2], h[2];
};

using FrameSides = std::map<int, Sides>;

// `margin`: stations next to the joint left out on each side.
FrameSides sides_by_frame(const SectionRun& a, const SectionRun& b, const std::vector<FrameStationSize>& views,
                          int margin = 0) {
  FrameSides by_frame;
  for (const FrameStationSize& v : views) {
    const bool before = v.station >= a.first && v.station <= a.last - margin;
    const bool after = v.station >= b.first + margin && v.station <= b.last;
    const int side = before ? 0 : after ? 1 : -1;
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

// Pose groups whose frames each measure the stepping dimension on both sides and see no step
// there. One view can be wrong where a step hides behind a plate (through the manhole, a wall
// and the one past its joint, a few millimetres apart, make one plane), so a step is taken
// back as it is confirmed: by `min_poses` pose groups. The station next to the joint on each
// side is left out: the joint lies on a station's edge only within the poses' error along the
// girder, so a frame whose view of one size ends there may have put its last centimetres of
// that size past the edge, and would "see it stay" where it saw only one side.
bool poses_see_it_stay(const SectionRun& a, const SectionRun& b, const JointEvidence& e) {
  const FrameSides frames = sides_by_frame(a, b, e.views, 1);
  const int dim = stepping_dimension(a, b);
  const double step = dim == 0 ? b.width_m - a.width_m : b.height_m - a.height_m;
  std::set<int> poses;
  for (const auto& [frame, s] : frames) {
    const std::vector<double>& before = dim == 0 ? s.w[0] : s.h[0];
    const std::vector<double>& after = dim == 0 ? s.w[1] : s.h[1];
    if (measured(before) && measured(after) && !steps(before, after, step, e.change_m))
      poses.insert(pose_of(frame, e.pose_groups));
  }
  return static_cast<int>(poses.size()) >= e.min_poses;
}

// The stretch a plate hides: one within reach of it, unless two pose groups see the size stay.
bool hidden_by_plate(const SectionRun& a, const SectionRun& b, const JointStretch& s, const JointEvidence& e) {
  if (poses_see_it_stay(a, b, e)) return false;
  return std::any_of(e.plate_stations.begin(), e.plate_stations.end(), [&](int p) {
    return p >= s.last_a - e.plate_reach && p <= s.first_b + e.plate_reach && p >= a.first && p < b.last;
  });
}

// Pose groups (other than `except`) whose frames' own sizes on one side are nearer that side's
// size than the other's: at least `min_poses` of them on each side.
bool each_side_measured(const SectionRun& a, const SectionRun& b, const FrameSides& frames, const JointEvidence& e,
                        const std::set<int>& except = {}) {
  const int dim = stepping_dimension(a, b);
  const double size[2] = {dim == 0 ? a.width_m : a.height_m, dim == 0 ? b.width_m : b.height_m};
  std::set<int> poses[2];
  for (const auto& [frame, s] : frames) {
    const int pose = pose_of(frame, e.pose_groups);
    if (except.count(pose)) continue;
    for (int side = 0; side < 2; ++side) {
      const double own = median_of_measured(dim == 0 ? s.w[side] : s.h[side]);
      if (std::abs(own - size[side]) < std::abs(own - size[1 - side])) poses[side].insert(pose);
    }
  }
  return static_cast<int>(poses[0].size()) >= e.min_poses && static_cast<int>(poses[1].size()) >= e.min_poses;
}

// Evidence a pose error cannot make: two poses' own frames see the step; or one does and the
// frames of enough other poses on each side measure their side's size (the case of a joint a
// plate hides, and a view of the step besides); or a plate hides it and they do.
bool joint_confirmed(const SectionRun& a, const SectionRun& b, const FrameSides& frames, const JointStretch& sized,
                     const JointEvidence& e) {
  const std::set<int> seeing = poses_seeing_step(a, b, frames, e);
  if (static_cast<int>(seeing.size()) >= e.min_poses) return true;
  if (!seeing.empty() && each_side_measured(a, b, frames, e, seeing) && !poses_see_it_stay(a, b, e))
    return true;
  return hidden_by_plate(a, b, sized, e) && each_side_measured(a, b, frames, e);
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

// `run` from `first` to `last` with its sizes taken again: where its own joint lies, and how
// much of it was seen, stays as it was.
SectionRun resized(const SectionRun& run, int first, int last, const SectionSplit& split, const std::vector<double>& w,
                   const std::vector<double>& h) {
  SectionRun r = with_medians(first, last, split, w, h);
  r.unseen_joint_stations = run.unseen_joint_stations;
  return r;
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
    const JointStretch sized = stretch_between(last, run, width_m, height_m);
    const JointStretch stretch = narrowed_by_walls(last, run, sized, e.wall_m);
    const bool confirmed = joint_confirmed(last, run, sides_by_frame(last, run, e.views), sized, e);
    if (confirmed && stretch.unmeasured() <= 0 && stretch.middle() == run.first) {  // seen where it lies
      out.sections.push_back(run);
      continue;
    }
    // Nothing measured where in the stretch the step lies (behind a plate, or between views
    // that saw both sides): the joint goes to its middle, at most half of it from the truth. A
    // step that was a short biased run next to a plate is gone once the sides are whole.
    if (confirmed) {
      const int joint = std::clamp(stretch.middle(), last.first + 1, run.last);
      const SectionRun before = resized(last, last.first, joint - 1, out, width_m, height_m);
      SectionRun after = with_medians(joint, run.last, out, width_m, height_m);
      after.unseen_joint_stations = stretch.unmeasured();
      if (differ(before, after, e.change_m)) {
        last = before;
        out.sections.push_back(after);
        continue;
      }
    }
    last = resized(last, last.first, run.last, out, width_m, height_m);
  }
  // Merging may leave neighbours of one size (a short biased run kept at a plate, then the run
  // after it merged back): they are one section.
  SectionSplit merged;
  merged.outlier = out.outlier;
  for (const SectionRun& run : out.sections) {
    if (!merged.sections.empty() && !differ(merged.sections.back(), run, e.change_m)) {
      SectionRun& last = merged.sections.back();
      last = resized(last, last.first, run.last, out, width_m, height_m);
    } else
      merged.sections.push_back(run);
  }
  return merged;
}

}  // namespace tunnelmap
