#include "core/normals/normal_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const NormalOptions& a, const NormalOptions& b) {
  return a.smoothing_px == b.smoothing_px && a.max_depth_change == b.max_depth_change;
}

NormalOptions normal_options(const Parameters& p) {
  NormalOptions o;
  o.smoothing_px = p.get(normal_keys::smoothing_px);
  o.max_depth_change = p.get(normal_keys::max_depth_change);
  return o;
}

ParameterGroup normal_parameter_group() {
  using namespace normal_keys;
  return {{smoothing_px.spec(), max_depth_change.spec()}, {}};
}

}  // namespace tunnelmap
