#include "core/mapping/wall_zone_layers.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tunnelmap {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMinSamples = 8;  // fewer place no surface

double weight(const LayerSample& s) { return 1.0 / std::max(1e-12, s.sigma_m * s.sigma_m); }

// The samples' plane insets, clustered (single linkage at `gap`), each cluster at its mean
// weighted by the samples' noise (cluster_zone_positions links alike but weighs by points, and
// its plain means moved the 100 m girder's corrected poses by up to 0.6 mm).
std::vector<double> initial_levels(const std::vector<LayerSample>& samples, double gap) {
  std::vector<std::pair<double, double>> insets;
  for (const LayerSample& s : samples) insets.push_back({s.inset_m, weight(s)});
  std::sort(insets.begin(), insets.end());
  std::vector<double> levels;
  double sum = 0.0, total = 0.0, last = -std::numeric_limits<double>::infinity();
  for (const auto& [inset, w] : insets) {
    if (inset - last > gap && total > 0.0) {
      levels.push_back(sum / total);
      sum = total = 0.0;
    }
    sum += w * inset;
    total += w;
    last = inset;
  }
  if (total > 0.0) levels.push_back(sum / total);
  return levels;
}

double smallest_gap(const std::vector<double>& levels) {
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < levels.size(); ++k) gap = std::min(gap, levels[k] - levels[k - 1]);
  return gap;
}

// The outer surface along the wall's normal: D + a s + b h + c s^2 at along-girder s and
// across-girder h (camera frame; a curve bends the wall along the girder only).
struct OuterSurface {
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  bool valid = false;
  static Eigen::Vector4d terms(double s, double h) { return {1.0, s, h, s * s}; }
  double at(double s, double h) const { return terms(s, h).dot(x); }
};

class LayerFit {
 public:
  LayerFit(const std::vector<LayerSample>& samples, const Eigen::Vector3d& outward, const Eigen::Vector3d& axis,
           const WallLayerOptions& o)
      : samples_(samples), options_(o), levels_(initial_levels(samples, o.min_gap_m)) {
    const Eigen::Vector3d across = outward.cross(axis).normalized();
    for (const LayerSample& s : samples) {
      depth_.push_back(outward.dot(s.point));
      along_.push_back(axis.dot(s.point));
      across_.push_back(across.dot(s.point));
    }
  }

  bool layered() const { return levels_.size() >= 2; }

  // The nearer half of the samples that resolve the levels, on the level nearest their plane's
  // inset: a straight surface through them (the far half are more often of merged planes).
  void start_from_near_samples() {
    std::vector<double> sigmas;
    for (const LayerSample& s : samples_)
      if (resolves(s)) sigmas.push_back(s.sigma_m);
    layer_.assign(samples_.size(), -1);
    if (sigmas.empty()) return;
    std::nth_element(sigmas.begin(), sigmas.begin() + sigmas.size() / 2, sigmas.end());
    const double near_sigma = sigmas[sigmas.size() / 2];
    for (std::size_t i = 0; i < samples_.size(); ++i)
      if (resolves(samples_[i]) && samples_[i].sigma_m <= near_sigma) layer_[i] = nearest(samples_[i].inset_m);
    fit_surface(false);
  }

  // The outer surface through the placed samples, each moved out by its level's inset.
  void fit_surface(bool curved) {
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    Eigen::Vector4d y = Eigen::Vector4d::Zero();
    int n = 0;
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      if (layer_[i] < 0) continue;
      const Eigen::Vector4d t = OuterSurface::terms(along_[i], across_[i]);
      const double w = weight(samples_[i]);
      A += w * t * t.transpose();
      y += w * t * (depth_[i] + levels_[static_cast<std::size_t>(layer_[i])]);
      ++n;
    }
    surface_.valid = n >= kMinSamples;
    if (!surface_.valid) return;
    surface_.x.setZero();
    if (curved) surface_.x = A.ldlt().solve(y);
    else surface_.x.head<3>() = A.topLeftCorner<3, 3>().ldlt().solve(y.head<3>());
  }

  // Each resolving sample on the level its own inset says; none when it lies between two.
  void assign_by_position() {
    const double reach = options_.between_fraction * smallest_gap(levels_);
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      layer_[i] = -1;
      if (!surface_.valid || !resolves(samples_[i])) continue;
      const double inset = inset_of(i);
      const int k = nearest(inset);
      if (std::abs(inset - levels_[static_cast<std::size_t>(k)]) <= reach) layer_[i] = k;
    }
  }

  // The levels' spacing as the samples measure it, the outermost level held. Two levels the
  // samples put less than `min_gap_m` apart are one zone (planes whose insets the frame
  // misjudged): they merge, or the noise of one zone would be cut in two, each half biased.
  void refine_levels() {
    std::vector<double> sum(levels_.size(), 0.0), total(levels_.size(), 0.0);
    for (std::size_t i = 0; i < samples_.size(); ++i) {
      if (layer_[i] < 0) continue;
      sum[static_cast<std::size_t>(layer_[i])] += weight(samples_[i]) * inset_of(i);
      total[static_cast<std::size_t>(layer_[i])] += weight(samples_[i]);
    }
    if (!(total[0] > 0.0)) return;
    std::vector<double> measured = levels_;
    for (std::size_t k = 1; k < levels_.size(); ++k)
      if (total[k] > 0.0) measured[k] = levels_[0] + sum[k] / total[k] - sum[0] / total[0];
    std::vector<std::size_t> order(levels_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return measured[a] < measured[b]; });
    std::vector<double> merged, weights;
    std::vector<int> renumbered(levels_.size(), 0);
    for (std::size_t k : order) {
      if (!merged.empty() && measured[k] - merged.back() < options_.min_gap_m) {
        // The outermost zone holds its inset; others merge at their weighted mean.
        if (merged.size() > 1)
          merged.back() = (merged.back() * weights.back() + measured[k] * total[k]) / (weights.back() + total[k]);
        weights.back() += total[k];
      } else {
        merged.push_back(measured[k]);
        weights.push_back(total[k]);
      }
      renumbered[k] = static_cast<int>(merged.size()) - 1;
    }
    for (int& layer : layer_)
      if (layer >= 0) layer = renumbered[static_cast<std::size_t>(layer)];
    levels_ = merged;
  }

  std::vector<double> result() const {
    std::vector<double> out(samples_.size(), kNaN);
    for (std::size_t i = 0; i < samples_.size(); ++i)
      if (layer_[i] >= 0) out[i] = levels_[static_cast<std::size_t>(layer_[i])];
    return out;
  }

 private:
  bool resolves(const LayerSample& s) const {
    return s.sigma_m <= options_.resolve_fraction * smallest_gap(levels_);
  }
  int nearest(double inset) const {
    int best = 0;
    for (std::size_t k = 1; k < levels_.size(); ++k)
      if (std::abs(inset - levels_[k]) < std::abs(inset - levels_[static_cast<std::size_t>(best)]))
        best = static_cast<int>(k);
    return best;
  }
  double inset_of(std::size_t i) const { return surface_.at(along_[i], across_[i]) - depth_[i]; }

  const std::vector<LayerSample>& samples_;
  WallLayerOptions options_;
  std::vector<double> levels_;
  std::vector<double> depth_, along_, across_;  // per sample: along the normal, the girder, across
  std::vector<int> layer_;
  OuterSurface surface_;
};

}  // namespace

std::vector<double> wall_zone_layers(const std::vector<LayerSample>& samples, const Eigen::Vector3d& outward,
                                     const Eigen::Vector3d& axis, const WallLayerOptions& options) {
  LayerFit fit(samples, outward.normalized(), axis.normalized(), options);
  if (!fit.layered()) {
    std::vector<double> insets;
    for (const LayerSample& s : samples) insets.push_back(s.inset_m);
    return insets;
  }
  fit.start_from_near_samples();
  for (int it = 0; it < options.iterations; ++it) {
    fit.assign_by_position();
    fit.refine_levels();
    fit.fit_surface(true);
  }
  fit.assign_by_position();
  return fit.result();
}

}  // namespace tunnelmap
