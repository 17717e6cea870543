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

// What the summary takes of one frame; the GUI keeps it per results-table row, so a document
// rebuilt from the rows has the summary `detect` prints.
struct SummaryEntry {
  bool detected = false;
  bool partial = false;
  std::optional<double> width_m, height_m;  // measured in the frame (not context or design)
  double total_ms = 0.0;
};
SummaryEntry summary_entry(const FrameResult& r);

// Mean and sample standard deviation (n - 1, core/report/statistics.h) of the width and height
// measured in the detected frames (the paper's mean(sigma)), plus errors against ground truth.
struct DetectionSummary {
  int frames = 0;
  int detected = 0;
  int partial = 0;  // of the detected, frames with a wall out of view
  double width_mean_m = 0, width_std_m = 0, height_mean_m = 0, height_std_m = 0;
  std::optional<double> gt_width_m, gt_height_m;
  double width_abs_error_mean_m = 0, height_abs_error_mean_m = 0;  // valid when gt is known
  double total_ms_median = 0;

  void add(const FrameResult& r) { add(summary_entry(r)); }
  void add(const SummaryEntry& e);
  void finish();
  nlohmann::json to_json() const;

 private:
  std::vector<double> widths_, heights_, totals_;
};

// The whole document: {"tool","version","method","input","params","frames","summary"}.
nlohmann::json detection_document(const nlohmann::json& params, const nlohmann::json& frames,
                                  const DetectionSummary& summary, const std::string& input);

// THE writer of a results document (`detect --json`, the GUI's results export): two-space
// indented, one trailing newline, written atomically.
void write_detection_json(const std::string& path, const nlohmann::json& document);

}  // namespace tunnelmap
