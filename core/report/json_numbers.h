#pragma once
// Numbers as the JSON outputs write them: vectors as arrays, values rounded to short decimals.
#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>

namespace tunnelmap {

inline nlohmann::json json_vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Rounds to `unit` (a power of ten below 1) so that the JSON shows short numbers: dividing by
// the exact integer scale gives the double nearest the decimal, which prints shortest.
inline double round_to(double v, double unit) {
  const double scale = std::round(1.0 / unit);
  return std::round(v * scale) / scale;
}

}  // namespace tunnelmap
