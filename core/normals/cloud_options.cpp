#include "core/normals/cloud_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const CloudOptions& a, const CloudOptions& b) {
  return a.min_range_m == b.min_range_m && a.max_range_m == b.max_range_m;
}

CloudOptions cloud_options(const Parameters& p) {
  CloudOptions o;
  o.min_range_m = p.get(cloud_keys::min_range_m);
  o.max_range_m = p.get(cloud_keys::max_range_m);
  return o;
}

ParameterGroup cloud_parameter_group() {
  using namespace cloud_keys;
  return {{max_range_m.spec(), min_range_m.spec()}, {less_than(min_range_m, max_range_m)}};
}

}  // namespace tunnelmap
