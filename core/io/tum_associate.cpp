#include "core/io/tum_associate.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace tunnelmap {

std::vector<int> associate_nearest(const std::vector<double>& queries,
                                   const std::vector<double>& candidates, double max_dt) {
  // Every pair within the limit (a window per query in the sorted candidates), sorted by gap.
  std::vector<std::tuple<double, int, int>> pairs;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const double t = queries[i];
    // The window is a little wider than the limit; the gap test below decides.
    auto j = std::lower_bound(candidates.begin(), candidates.end(), t - max_dt - 1e-6);
    for (; j != candidates.end() && *j <= t + max_dt + 1e-6; ++j) {
      const double gap = std::abs(*j - t);
      if (gap <= max_dt)
        pairs.emplace_back(gap, static_cast<int>(i), static_cast<int>(j - candidates.begin()));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> match(queries.size(), -1);
  std::vector<bool> used(candidates.size(), false);
  for (const auto& [gap, i, j] : pairs) {
    if (match[static_cast<std::size_t>(i)] >= 0 || used[static_cast<std::size_t>(j)]) continue;
    match[static_cast<std::size_t>(i)] = j;
    used[static_cast<std::size_t>(j)] = true;
  }
  return match;
}

namespace {
Eigen::Isometry3d pose_of(const TumPoseEntry& s) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = s.rotation.toRotationMatrix();
  p.translation() = s.translation;
  return p;
}
}  // namespace

std::optional<Eigen::Isometry3d> interpolate_pose(const std::vector<TumPoseEntry>& samples, double t,
                                                  double max_dt) {
  if (samples.empty()) return std::nullopt;
  if (t <= samples.front().timestamp_s) {
    if (samples.front().timestamp_s - t <= max_dt) return pose_of(samples.front());
    return std::nullopt;
  }
  if (t >= samples.back().timestamp_s) {
    if (t - samples.back().timestamp_s <= max_dt) return pose_of(samples.back());
    return std::nullopt;
  }
  // First sample after t; t lies in (a, b].
  const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                      [](double x, const TumPoseEntry& s) { return x < s.timestamp_s; });
  const TumPoseEntry& a = *(after - 1);
  const TumPoseEntry& b = *after;
  if (t == a.timestamp_s) return pose_of(a);
  // Halved differences cannot overflow, whatever the timestamps' size.
  const double alpha = std::clamp((t / 2 - a.timestamp_s / 2) / (b.timestamp_s / 2 - a.timestamp_s / 2), 0.0, 1.0);
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.linear() = a.rotation.slerp(alpha, b.rotation).normalized().toRotationMatrix();
  p.translation() = (1.0 - alpha) * a.translation + alpha * b.translation;
  return p;
}

}  // namespace tunnelmap
