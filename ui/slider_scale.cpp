#include "ui/slider_scale.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap::ui {

namespace {
constexpr double kLogDecades = 1000.0;  // max / smallest step above 0 at which the scale turns logarithmic
constexpr int kLogPositions = 1000;
}  // namespace

SliderScale::SliderScale(const ParameterSpec& spec) : spec_(spec) {
  const double lowest = std::max(spec.min, spec.step);
  logarithmic_ = lowest > 0.0 && spec.max / lowest >= kLogDecades;
  if (!logarithmic_) {
    positions_ = static_cast<int>(std::lround((spec.max - spec.min) / spec.step));
    return;
  }
  positions_ = kLogPositions;
  log_low_ = lowest;
}

double SliderScale::snapped(double value) const {
  double v = spec_.min + std::round((value - spec_.min) / spec_.step) * spec_.step;
  if (spec_.integer) v = std::round(v);
  return std::clamp(v, spec_.min, spec_.max);
}

// A range from 0 keeps position 0 for the value 0 and spreads the rest from one step upwards.
int SliderScale::to_slider(double value) const {
  if (!logarithmic_) return static_cast<int>(std::lround((value - spec_.min) / spec_.step));
  const bool from_zero = spec_.min < log_low_;
  if (from_zero && value < log_low_) return 0;
  const int first = from_zero ? 1 : 0;
  const double t = std::log(value / log_low_) / std::log(spec_.max / log_low_);
  return first + static_cast<int>(std::lround(t * (positions_ - first)));
}

double SliderScale::from_slider(int position) const {
  if (!logarithmic_) return std::min(spec_.max, spec_.min + position * spec_.step);
  const bool from_zero = spec_.min < log_low_;
  if (from_zero && position == 0) return spec_.min;
  const int first = from_zero ? 1 : 0;
  const double t = static_cast<double>(position - first) / (positions_ - first);
  return snapped(log_low_ * std::pow(spec_.max / log_low_, t));
}

}  // namespace tunnelmap::ui
