#include "core/sim/sensor_model.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap::sim {

namespace {
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kDeg = 3.14159265358979323846 / 180.0;
}  // namespace

double axial_sigma_m(double depth_m, double incidence_rad) {
  const double z = std::max(depth_m, 1e-3);
  const double theta = std::clamp(std::abs(incidence_rad), 0.0, kMaxModelAngleRad);
  double sigma = 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4);
  if (theta > 60.0 * kDeg) {
    const double r = theta / (kHalfPi - theta);
    sigma += 0.0001 / std::sqrt(z) * r * r;
  }
  return sigma;
}

double lateral_sigma_px(double incidence_rad) {
  const double theta = std::clamp(std::abs(incidence_rad), 0.0, kMaxModelAngleRad);
  return 0.8 + 0.035 * theta / (kHalfPi - theta);
}

double quantize_depth_m(double depth_m, double fx, double baseline_m, int steps) {
  if (!(depth_m > 0.0)) return 0.0;
  const double d = fx * baseline_m / depth_m;
  const double dq = std::round(d * steps) / steps;
  return dq > 0.0 ? fx * baseline_m / dq : 0.0;
}

double quantization_step_m(double depth_m, double fx, double baseline_m, int steps) {
  return depth_m * depth_m / (fx * baseline_m * steps);
}

double tof_sigma_m(double depth_m, double incidence_rad, double base_m, double per_m) {
  const double c = std::max(std::cos(std::abs(incidence_rad)), 0.1);
  return (base_m + per_m * std::max(depth_m, 0.0)) / std::sqrt(c);
}

double grazing_dropout_probability(double incidence_rad, double start_deg, double full_deg) {
  const double s = (std::abs(incidence_rad) / kDeg - start_deg) / (full_deg - start_deg);
  if (s <= 0.0) return 0.0;
  if (s >= 1.0) return 1.0;
  return s * s;
}

}  // namespace tunnelmap::sim
