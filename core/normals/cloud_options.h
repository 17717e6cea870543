#pragma once
// Stage 2a's parameters (cloud.*), declared once, and the options build_cloud takes.
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace cloud_keys {
inline constexpr ParameterKey<double> max_range_m{
    "cloud.max_range_m", "m", 5.0, 0.5, 12.0, 0.1, Stage::Cloud, "Max range",
    "Max usable range from the sensing plane; farther pixels are ignored (paper: 5 m)"};
inline constexpr ParameterKey<double> min_range_m{
    "cloud.min_range_m", "m", 0.3, 0.0, 2.0, 0.05, Stage::Cloud, "Min range",
    "Pixels nearer than this are ignored (below the sensor's working range)"};
}  // namespace cloud_keys

struct CloudOptions {
  double min_range_m = cloud_keys::min_range_m.default_value;
  double max_range_m = cloud_keys::max_range_m.default_value;
};
bool operator==(const CloudOptions& a, const CloudOptions& b);
inline bool operator!=(const CloudOptions& a, const CloudOptions& b) { return !(a == b); }

CloudOptions cloud_options(const Parameters& p);
ParameterGroup cloud_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
