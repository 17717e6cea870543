#include "core/io/input_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const InputLimitOptions& a, const InputLimitOptions& b) {
  return a.max_image_pixels == b.max_image_pixels;
}

InputLimitOptions input_limit_options(const Parameters& p) {
  InputLimitOptions o;
  o.max_image_pixels = p.get(input_keys::max_image_pixels);
  return o;
}

ParameterGroup input_parameter_group() { return {{input_keys::max_image_pixels.spec()}, {}}; }

}  // namespace tunnelmap
