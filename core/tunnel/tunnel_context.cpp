// TunnelContext: the widths/heights accepted from earlier scans of a sequence; medians resist
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

void TunnelContext::accept(const TunnelMap& map) {
  if (!map.detected) return;  // only detected maps define the context
  if (widths_.size() < kWindow) {
    if (widths_.empty()) {  // the whole window at once: no reallocation while it fills
      widths_.reserve(kWindow);
      heights_.reserve(kWindow);
    }
    widths_.push_back(map.width_m);
    heights_.push_back(map.height_m);
    return;
  }
  widths_[next_] = map.width_m;
  heights_[next_] = map.height_m;
  next_ = (next_ + 1) % kWindow;
}

double TunnelContext::width_m() const { return median(widths_); }
double TunnelContext::height_m() const { return median(heights_); }

}  // namespace tunnelmap
