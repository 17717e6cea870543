// TunnelContext: the widths/heights measured by earlier scans of a sequence; medians resist
// the occasional bad frame that slipped through.
#include <algorithm>
#include <vector>

#include "core/tunnel/tunnel_detector.h"

namespace tunnelmap {

namespace {
// `v` is scratch: its buffer is reused (no allocation per frame in the steady state).
double median_of(const std::vector<double>& values, std::vector<double>& v) {
  if (values.empty()) return 0.0;
  v.assign(values.begin(), values.end());
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  const double hi = v[mid];
  if (v.size() % 2 == 1) return hi;
  const double lo = *std::max_element(v.begin(), v.begin() + mid);
  return 0.5 * (lo + hi);
}
}  // namespace

void TunnelContext::Ring::push(double v) {
  if (values.size() < kWindow) {
    if (values.empty()) {  // no reallocation while the window fills
      values.reserve(kWindow);
      work.reserve(kWindow);
    }
    values.push_back(v);
  } else {
    values[next] = v;
    next = (next + 1) % kWindow;
  }
  median = median_of(values, work);
}

void TunnelContext::accept(const TunnelMap& map) {
  // Only measured dimensions define the context: an inferred one would confirm itself.
  if (map.width_measured()) width_.push(map.width_m);
  if (map.height_measured()) height_.push(map.height_m);
}

}  // namespace tunnelmap
