#include "core/tunnel/normal_outliers.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace tunnelmap {

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 stays accurate for the tiny angles that matter here (acos does not).
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
}

namespace {

Eigen::Vector3d weighted_mean(const std::vector<WeightedNormal>& normals,
                              const std::vector<bool>& use) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < normals.size(); ++i)
    if (use[i]) sum += normals[i].weight * normals[i].normal;
  return sum.norm() > 0 ? Eigen::Vector3d(sum.normalized()) : Eigen::Vector3d::Zero();
}

// Mode seeking: the plane with the most weight within max_deg / 2 of it, and the mean of
// those neighbours. A plain mean would be dragged by heavy outliers before the histogram runs.
Eigen::Vector3d robust_seed(const std::vector<WeightedNormal>& normals, double max_deg,
                            std::vector<bool>& use) {
  const double radius = 0.5 * max_deg;
  size_t best = 0;
  double best_weight = -1.0;
  for (size_t i = 0; i < normals.size(); ++i) {
    double w = 0.0;
    for (const auto& m : normals)
      if (angle_deg(normals[i].normal, m.normal) <= radius) w += m.weight;
    if (w > best_weight) { best_weight = w; best = i; }
  }
  use.resize(normals.size());
  for (size_t i = 0; i < normals.size(); ++i)
    use[i] = angle_deg(normals[best].normal, normals[i].normal) <= radius;
  return weighted_mean(normals, use);
}

// Fills `in` (one flag per normal).
void histogram_inliers(const std::vector<WeightedNormal>& normals, const Eigen::Vector3d& mean,
                       double bin_deg, double max_deg, OutlierScratch& s, std::vector<bool>& in) {
  const int bins = std::max(1, static_cast<int>(std::ceil(max_deg / bin_deg)));
  std::vector<double>& weight = s.weight;
  std::vector<int>& bin_of = s.bin_of;  // -1: beyond max_deg, always an outlier
  weight.assign(bins, 0.0);
  bin_of.assign(normals.size(), -1);
  for (size_t i = 0; i < normals.size(); ++i) {
    const double d = angle_deg(mean, normals[i].normal);
    if (d > max_deg) continue;
    bin_of[i] = std::min(bins - 1, static_cast<int>(d / bin_deg));
    weight[bin_of[i]] += normals[i].weight;
  }
  const int peak = static_cast<int>(std::max_element(weight.begin(), weight.end()) - weight.begin());
  int last = peak;  // last kept bin: the main mode ends at the first empty bin after the peak
  while (last + 1 < bins && weight[last + 1] > 0.0) ++last;
  in.resize(normals.size());
  for (size_t i = 0; i < normals.size(); ++i) in[i] = bin_of[i] >= 0 && bin_of[i] <= last;
}

}  // namespace

NormalClassStats reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                                        double max_deg) {
  NormalClassStats s;
  reject_normal_outliers(normals, bin_deg, max_deg, s);
  return s;
}

void reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                            double max_deg, NormalClassStats& s) {
  OutlierScratch scratch;
  reject_normal_outliers(normals, bin_deg, max_deg, s, scratch);
}

void reject_normal_outliers(const std::vector<WeightedNormal>& normals, double bin_deg,
                            double max_deg, NormalClassStats& s, OutlierScratch& scr) {
  s.valid = false;
  s.mean = Eigen::Vector3d::Zero();
  s.sd_deg = 0.0;
  s.inlier.assign(normals.size(), false);
  if (normals.empty()) return;
  Eigen::Vector3d mean = robust_seed(normals, max_deg, scr.use);
  for (int iter = 0; iter < 4 && mean.norm() > 0; ++iter) {
    histogram_inliers(normals, mean, bin_deg, max_deg, scr, scr.in);
    const Eigen::Vector3d next = weighted_mean(normals, scr.in);
    const bool same = scr.in == s.inlier;
    s.inlier.swap(scr.in);  // swap, not move: both buffers stay for the next call
    mean = next;
    if (same) break;
  }
  if (mean.norm() == 0) {
    s.inlier.assign(normals.size(), false);
    return;
  }
  s.valid = true;
  s.mean = mean;
  double w = 0.0, sq = 0.0;
  for (size_t i = 0; i < normals.size(); ++i) {
    if (!s.inlier[i]) continue;
    const double d = angle_deg(mean, normals[i].normal);
    w += normals[i].weight;
    sq += normals[i].weight * d * d;
  }
  s.sd_deg = w > 0 ? std::sqrt(sq / w) : 0.0;
}

}  // namespace tunnelmap
