#pragma once
// How a parameter's value maps to slider positions. Linear in the parameter's steps, unless the
// range spans three decades or more (min points 3 to 100,000): then logarithmic, so a short drag
// changes the value by a factor, not by thousands (on a linear slider of 200 px one pixel of
// min points is 500 points).
#include "core/params/parameter_key.h"

namespace tunnelmap::ui {

class SliderScale {
 public:
  explicit SliderScale(const ParameterSpec& spec);

  bool logarithmic() const { return logarithmic_; }
  int positions() const { return positions_; }  // the slider's maximum (its minimum is 0)
  int to_slider(double value) const;
  double from_slider(int position) const;  // a value of the table's step, within its range

 private:
  double snapped(double value) const;

  ParameterSpec spec_;
  bool logarithmic_ = false;
  int positions_ = 0;
  double log_low_ = 0.0;  // logarithmic: the value of position 1 (0 when the range starts at 0)
};

}  // namespace tunnelmap::ui
