#include "core/evaluation/truth_line.h"

#include <algorithm>
#include <limits>

namespace tunnelmap {

namespace {

Eigen::Vector3d vec3(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

}  // namespace

TruthLine::TruthLine(const nlohmann::json& line) {
  for (const auto& p : line) s_.push_back(p["station_m"].get<double>()), x_.push_back(vec3(p["point"]));
}

double TruthLine::station_of(const Eigen::Vector3d& p) const {
  if (x_.size() < 2) return s_.empty() ? 0.0 : s_[0];
  return refined(p, nearest(p));
}

double TruthLine::station_near(const Eigen::Vector3d& p, std::size_t near, std::size_t reach) const {
  if (x_.size() < 2) return s_.empty() ? 0.0 : s_[0];
  const std::size_t from = near > reach ? near - reach : 0;
  return refined(p, nearest_within(p, from, std::min(x_.size(), near + reach + 1)));
}

std::size_t TruthLine::nearest(const Eigen::Vector3d& p) const { return nearest_within(p, 0, x_.size()); }

Eigen::Vector3d TruthLine::direction_at(const Eigen::Vector3d& p) const {
  return x_.size() < 2 ? Eigen::Vector3d::UnitX() : direction_near(nearest(p));
}

std::size_t TruthLine::nearest_within(const Eigen::Vector3d& p, std::size_t from, std::size_t to) const {
  std::size_t best = from;
  double d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = from; i < to; ++i)
    if (const double d = (x_[i] - p).squaredNorm(); d < d2) d2 = d, best = i;
  return best;
}

double TruthLine::refined(const Eigen::Vector3d& p, std::size_t i) const {
  return s_[i] + direction_near(i).dot(p - x_[i]);
}

Eigen::Vector3d TruthLine::direction_near(std::size_t i) const {
  const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(x_.size() - 1, i + 1);
  return (x_[b] - x_[a]).normalized();
}

}  // namespace tunnelmap
