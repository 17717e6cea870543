#pragma once
// The readers' parameters (input.*), declared once, and the plain limits the readers take
// (ReadOptions), so that no decoder needs the parameter table.
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace input_keys {
// 4096 x 4096 is four times the largest depth camera's frame; an 8192 x 8192 frame would take
// over 2 GB through the pipeline. The upper end is the readers' hard limit on a side, squared.
inline constexpr ParameterKey<int> max_image_pixels{
    "input.max_image_pixels", "px", 4096 * 4096, 100, 8192 * 8192, 1, Stage::Cloud, "Max image pixels",
    "Depth, colour, label and .oni frames with more pixels are refused from their header, before decoding"};
}  // namespace input_keys

struct InputLimitOptions {
  long long max_image_pixels = input_keys::max_image_pixels.default_value;
};
bool operator==(const InputLimitOptions& a, const InputLimitOptions& b);
inline bool operator!=(const InputLimitOptions& a, const InputLimitOptions& b) { return !(a == b); }

InputLimitOptions input_limit_options(const Parameters& p);
ParameterGroup input_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
