// TunnelContext: the widths/heights measured by earlier scans of a sequence; medians resist
// the occasional bad frame that slipped through.
#include <algorithm>
#include <vector>

#include "core/tunnel/tunnel_detector.h"

namespace tunnelmap {

namespace {
double median(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  thread_local std::vector<double> v;  // scratch: no allocation per frame in the steady state
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
    if (values.empty()) values.reserve(kWindow);  // no reallocation while the window fills
    values.push_back(v);
    return;
  }
  values[next] = v;
  next = (next + 1) % kWindow;
}

void TunnelContext::accept(const TunnelMap& map) {
  // Only measured dimensions define the context: an inferred one would confirm itself.
  if (map.width_measured()) width_.push(map.width_m);
  if (map.height_measured()) height_.push(map.height_m);
}

double TunnelContext::width_m() const { return median(width_.values); }
double TunnelContext::height_m() const { return median(height_.values); }

}  // namespace tunnelmap
