#pragma once
// Results of one method on one cell of the evaluation (a pose of the lab replica, a distance
// of the field replica, a sweep value or a user dataset): the paper's mean(sigma) plus errors
// against ground truth, detection rate, speed and segmentation quality.
#include <optional>
#include <string>
#include <vector>

#include "core/baselines/method.h"
#include "core/evaluation/segmentation_metrics.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

struct CellResult {
  std::string experiment;  // "lab", "field", a sweep name or a dataset folder
  std::string cell;        // "Pose 1", "5m to plate", "noise_scale=2", ...
  double cell_value = 0;   // sweep value (0 for Table 1 cells)
  Method method = Method::Pgc;
  std::optional<double> gt_width_m, gt_height_m;
  int frames = 0, detected = 0;
  double width_mean_m = 0, width_std_m = 0, height_mean_m = 0, height_std_m = 0;  // detected frames
  double width_abs_error_m = 0, height_abs_error_m = 0;  // mean |error| over detected frames
  double ms_mean = 0;      // mean wall-clock ms per frame (all stages)
  bool has_segmentation = false;
  SegmentationScore segmentation;

  double detection_rate() const { return frames ? double(detected) / frames : 0.0; }
  double fps() const { return ms_mean > 0 ? 1000.0 / ms_mean : 0.0; }
  // Mean of the width and height |errors| (mm); NaN when nothing was detected or no truth.
  double mean_abs_error_mm() const;
};

// Collects frames of one method on one cell.
class CellAccumulator {
 public:
  void add(const FrameResult& r, const std::vector<std::uint16_t>* truth);
  // Fills the statistics of `out` (labels and method are the caller's).
  void finish(CellResult& out) const;

 private:
  std::vector<double> widths_, heights_, ms_;
  int frames_ = 0;
  bool has_segmentation_ = false;
  SegmentationScore segmentation_;
};

}  // namespace tunnelmap
