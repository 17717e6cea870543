#pragma once
// Machine-readable results of `detect` and `planes` (the JSON layout is a contract users'
// scripts rely on: fields may be added, never renamed) and the per-sequence summary.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/pipeline/pipeline.h"

namespace tunnelmap {

// {"index","source","detected","status","reason","width_m","height_m","planes","walls":{...},
//  "axis":{...},"timings_ms":{...}}; walls are in the camera frame.
nlohmann::json detection_frame_json(std::size_t index, const std::string& source,
                                    const FrameResult& result);

// {"index","source","planes":[{"id","normal","centroid","points","area_m2",...}],"timings_ms"}.
nlohmann::json planes_frame_json(std::size_t index, const std::string& source,
                                 const PlaneSegments& planes, const StageTimings& timings_ms);

// Mean and population standard deviation of the detected frames' width and height (the
// paper's mean(sigma)), plus errors against ground truth when known.
struct DetectionSummary {
  int frames = 0;
  int detected = 0;
  int partial = 0;  // of the detected, frames with a wall out of view
  double width_mean_m = 0, width_std_m = 0, height_mean_m = 0, height_std_m = 0;
  std::optional<double> gt_width_m, gt_height_m;
  double width_abs_error_mean_m = 0, height_abs_error_mean_m = 0;  // valid when gt is known
  double total_ms_median = 0;

  void add(const FrameResult& r);
  void finish();
  nlohmann::json to_json() const;

 private:
  std::vector<double> widths_, heights_, totals_;
};

// The whole document: {"tool","version","method","params","frames","summary"}.
nlohmann::json detection_document(const nlohmann::json& params, const nlohmann::json& frames,
                                  const DetectionSummary& summary, const std::string& input);

// One CSV row per frame (header first) for spreadsheets.
std::string detection_csv(const nlohmann::json& frames);

}  // namespace tunnelmap
