#include "core/evaluation/cell_result.h"

#include <cmath>
#include <limits>

#include "core/report/statistics.h"

namespace tunnelmap {

double CellResult::mean_abs_error_mm() const {
  if (detected == 0 || !gt_width_m || !gt_height_m) return std::numeric_limits<double>::quiet_NaN();
  return 500.0 * (width_abs_error_m + height_abs_error_m);
}

void CellAccumulator::add(const FrameResult& r, const std::vector<std::uint16_t>* truth) {
  ++frames_;
  ms_.push_back(r.timings_ms.count("total") ? r.timings_ms.at("total") : 0.0);
  if (r.map.width_measured() && r.map.height_measured()) {  // inferred values are not measurements
    widths_.push_back(r.map.width_m);
    heights_.push_back(r.map.height_m);
  }
  if (truth && !truth->empty() && !r.planes.labels.empty()) {
    has_segmentation_ = true;
    segmentation_ += score_segmentation(r.planes, *truth);
  }
}

void CellAccumulator::finish(CellResult& out) const {
  out.frames = frames_;
  out.detected = static_cast<int>(widths_.size());
  const MeanSigma w = mean_sigma(widths_), h = mean_sigma(heights_);  // sample sigma, Table 1
  out.width_mean_m = w.mean;
  out.width_std_m = w.sigma;
  out.height_mean_m = h.mean;
  out.height_std_m = h.sigma;
  if (out.gt_width_m) out.width_abs_error_m = mean_abs_error(widths_, *out.gt_width_m);
  if (out.gt_height_m) out.height_abs_error_m = mean_abs_error(heights_, *out.gt_height_m);
  double ms = 0;
  for (double x : ms_) ms += x;
  out.ms_mean = ms_.empty() ? 0 : ms / ms_.size();
  out.has_segmentation = has_segmentation_;
  out.segmentation = segmentation_;
}

}  // namespace tunnelmap
