#include "core/mapping/section_evidence.h"

#include <cmath>
#include <map>
#include <set>

#include "core/util/median.h"

namespace tunnelmap {

namespace {

// A frame's own sizes over one section's stations.
struct Sides {
  std::vector<double> w[2], h[2];
};

bool steps(const std::vector<double>& before, const std::vector<double>& after, double section_step, double change) {
  const double a = median_of_measured(before), b = median_of_measured(after);
  if (std::isnan(a) || std::isnan(b) || std::isnan(section_step)) return false;
  return std::abs(b - a) > change && (b - a) * section_step > 0;
}

// Pose groups whose frames measure, each on its own, the step from section `a` to section `b`.
std::set<int> poses_seeing_step(const SectionRun& a, const SectionRun& b, const std::vector<FrameStationSize>& views,
                                const std::vector<int>& pose_groups, double change) {
  std::map<int, Sides> by_frame;
  for (const FrameStationSize& v : views) {
    const int side = v.station >= a.first && v.station <= a.last ? 0 : v.station >= b.first && v.station <= b.last ? 1 : -1;
    if (side < 0) continue;
    Sides& s = by_frame[v.frame];
    s.w[side].push_back(v.width_m);
    s.h[side].push_back(v.height_m);
  }
  std::set<int> poses;
  for (const auto& [frame, s] : by_frame) {
    if (!steps(s.w[0], s.w[1], b.width_m - a.width_m, change) && !steps(s.h[0], s.h[1], b.height_m - a.height_m, change))
      continue;
    const bool grouped = frame >= 0 && frame < static_cast<int>(pose_groups.size());
    poses.insert(grouped ? pose_groups[static_cast<std::size_t>(frame)] : -1 - frame);
  }
  return poses;
}

// The section from a.first to b.last, its size the median of its accepted stations.
SectionRun merged(const SectionRun& a, const SectionRun& b, const SectionSplit& split, const std::vector<double>& w,
                  const std::vector<double>& h) {
  std::vector<double> sw, sh;
  for (int k = a.first; k <= b.last; ++k) {
    if (split.outlier[static_cast<std::size_t>(k)]) continue;
    sw.push_back(w[static_cast<std::size_t>(k)]);
    sh.push_back(h[static_cast<std::size_t>(k)]);
  }
  return {a.first, b.last, median_of_measured(sw), median_of_measured(sh)};
}

}  // namespace

SectionSplit keep_confirmed_joints(const SectionSplit& split, const std::vector<double>& width_m,
                                   const std::vector<double>& height_m, const std::vector<FrameStationSize>& views,
                                   const std::vector<int>& pose_groups, double change_m, int min_poses) {
  SectionSplit out;
  out.outlier = split.outlier;
  for (const SectionRun& run : split.sections) {
    if (out.sections.empty()) {
      out.sections.push_back(run);
      continue;
    }
    SectionRun& last = out.sections.back();
    const auto poses = poses_seeing_step(last, run, views, pose_groups, change_m);
    if (static_cast<int>(poses.size()) >= min_poses) out.sections.push_back(run);
    else last = merged(last, run, out, width_m, height_m);
  }
  return out;
}

}  // namespace tunnelmap
