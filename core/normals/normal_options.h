#pragma once
// Stage 2b's parameters (normals.*), declared once, and the options estimate_normals takes.
#include "core/params/parameter_key.h"

namespace tunnelmap {

class Parameters;

namespace normal_keys {
inline constexpr ParameterKey<int> smoothing_px{
    "normals.smoothing_px", "px", 10, 3, 41, 1, Stage::Normals, "Normal window",
    "Side of the integral-image smoothing window used for per-pixel normals (Holzer et al.)"};
inline constexpr ParameterKey<double> max_depth_change{
    "normals.max_depth_change", "", 0.15, 0.005, 1.0, 0.005, Stage::Normals, "Discontinuity limit",
    "Relative second difference of inverse depth that marks a depth edge (no normal near it); planes give 0"};
}  // namespace normal_keys

struct NormalOptions {
  int smoothing_px = normal_keys::smoothing_px.default_value;  // side of the box window
  // Relative 2nd difference of inverse depth = edge.
  double max_depth_change = normal_keys::max_depth_change.default_value;
};
bool operator==(const NormalOptions& a, const NormalOptions& b);
inline bool operator!=(const NormalOptions& a, const NormalOptions& b) { return !(a == b); }

NormalOptions normal_options(const Parameters& p);
ParameterGroup normal_parameter_group();  // table rows and rules, in table order

}  // namespace tunnelmap
