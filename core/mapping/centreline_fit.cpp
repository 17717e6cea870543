#include "core/mapping/centreline_fit.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace tunnelmap {

namespace {

bool measured(const TunnelMap& m) {
  return m.detected && m.width_source == DimensionSource::Measured && m.height_source == DimensionSource::Measured;
}

// Each sample's position along the walk: the first sample at 0, each next one advanced by the
// step between their centres along their mean axis (axes turned to agree with `forward`).
std::vector<double> walk_positions(const std::vector<CentreSample>& samples, const Eigen::Vector3d& forward,
                                   std::vector<Eigen::Vector3d>& axes) {
  std::vector<double> t(samples.size(), 0.0);
  axes.resize(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3d& before = i == 0 ? forward : axes[i - 1];
    axes[i] = samples[i].axis.dot(before) < 0 ? -samples[i].axis : samples[i].axis;
    if (i > 0) t[i] = t[i - 1] + (axes[i - 1] + axes[i]).normalized().dot(samples[i].point - samples[i - 1].point);
  }
  return t;
}

// A node's fit is trusted only when its point is within twice one frame's centre noise, and its
// direction as certain as two centres this far apart make it: the frames of one stop lie
// millimetres apart, and a slope fitted across them alone is their noise over those
// millimetres (nodes stood a metre off where the frames near a plate leave a stretch
// unmeasured). A quadratic bridging such a stretch from both sides passes (its point within
// about 1.5 centres' noise); one fitted to two stops does not (thousands).
constexpr double kMaxPointVariance = 4.0;  // in units of one centre's variance
constexpr double kMinDirectionBaseM = 0.5;

// The node at walk position `tau`: a weighted local quadratic (linear where the samples do not
// support a quadratic) of the centres against their positions; its value is the point, its
// slope the axis. Tricube weights fade the window's ends, so nodes move smoothly. False when
// the samples in the window support not even a line.
bool fit_node(const std::vector<CentreSample>& samples, const std::vector<double>& t,
              const std::vector<Eigen::Vector3d>& axes, double tau, double window, CentrelineFrame& node) {
  for (const int degree : {2, 1}) {
    const int k = degree + 1;
    // A: the weighted normal matrix; W2: the same with squared weights, so that A^-1 W2 A^-1 is
    // the fit's covariance in units of one centre's variance.
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero(), W2 = Eigen::Matrix3d::Zero(), B = Eigen::Matrix3d::Zero();
    Eigen::Vector3d up = Eigen::Vector3d::Zero(), axis = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double d = t[i] - tau;
      if (std::abs(d) >= window) continue;
      const double r = 1.0 - std::pow(std::abs(d) / window, 3);
      const double w = r * r * r;
      const Eigen::Vector3d phi(1.0, d, d * d);
      A.topLeftCorner(k, k) += w * phi.head(k) * phi.head(k).transpose();
      W2.topLeftCorner(k, k) += w * w * phi.head(k) * phi.head(k).transpose();
      B.topRows(k) += w * phi.head(k) * samples[i].point.transpose();
      up += w * samples[i].up;
      axis += w * axes[i];
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A.topLeftCorner(k, k));
    if (lu.rank() < k) continue;
    const Eigen::MatrixXd Ainv = lu.inverse();
    const Eigen::MatrixXd covariance = Ainv * W2.topLeftCorner(k, k) * Ainv;
    const double max_slope_variance = 2.0 / (kMinDirectionBaseM * kMinDirectionBaseM);
    if (!(covariance(0, 0) <= kMaxPointVariance) || !(covariance(1, 1) <= max_slope_variance)) continue;
    const Eigen::MatrixXd X = Ainv * B.topRows(k);
    const Eigen::Vector3d slope = X.row(1).transpose();
    node.point = X.row(0).transpose();
    node.axis = slope.norm() > 0.5 ? slope.normalized() : axis.normalized();
    node.up = (up - node.axis * node.axis.dot(up)).normalized();
    return node.up.allFinite() && node.axis.allFinite();
  }
  return false;
}

// Nodes every `step` along the walk positions, stations their arc length.
std::vector<CentrelineFrame> fit_nodes(const std::vector<CentreSample>& samples, const std::vector<double>& t,
                                       const std::vector<Eigen::Vector3d>& axes, double step, double window) {
  const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
  const int count = static_cast<int>(std::floor((*hi - *lo) / step)) + 1;
  std::vector<CentrelineFrame> nodes;
  for (int j = 0; j < count; ++j) {
    CentrelineFrame node;
    if (!fit_node(samples, t, axes, *lo + j * step, window, node)) continue;
    node.station_m = nodes.empty() ? 0.0 : nodes.back().station_m + (node.point - nodes.back().point).norm();
    nodes.push_back(node);
  }
  return nodes;
}

}  // namespace

std::vector<CentreSample> centre_samples(const std::vector<TunnelMap>& maps,
                                         const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<CentreSample> out;
  for (std::size_t i = 0; i < maps.size() && i < poses.size(); ++i) {
    const TunnelMap& m = maps[i];
    if (!measured(m)) continue;
    const Eigen::Vector3d a = m.axis_dir.normalized();
    // The centre line's point abreast of the camera (the camera's centre is the origin).
    const Eigen::Vector3d centre = m.axis_point - a * a.dot(m.axis_point);
    out.push_back({poses[i] * centre, poses[i].linear() * a, poses[i].linear() * m.up.normalized()});
  }
  return out;
}

std::optional<Centreline> fit_centreline(const std::vector<CentreSample>& samples, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& forward, const StationMapOptions& options) {
  if (samples.size() < 3) return std::nullopt;
  const double window = options.centreline_window_m;
  std::vector<Eigen::Vector3d> axes;
  std::vector<double> t = walk_positions(samples, forward, axes);
  const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
  if (*hi - *lo < 2.0 * window) return std::nullopt;
  // The walk's positions are the arc length only as far as the axes are right: fit, take each
  // sample's station on the fitted line as its position, and fit again.
  std::vector<CentrelineFrame> nodes;
  for (int pass = 0; pass < 2; ++pass) {
    nodes = fit_nodes(samples, t, axes, options.centreline_node_m, window);
    if (nodes.size() < 2) return std::nullopt;
    const Centreline line = Centreline::through(nodes);
    for (std::size_t i = 0; i < samples.size(); ++i) t[i] = line.locate(samples[i].point).station_m;
  }
  const double zero = Centreline::through(nodes).locate(origin).station_m;
  for (CentrelineFrame& n : nodes) n.station_m -= zero;
  return Centreline::through(std::move(nodes));
}

}  // namespace tunnelmap
