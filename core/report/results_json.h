#pragma once
// Machine-readable results of `detect` and `planes` (the JSON layout is a contract users'
// scripts rely on: fields may be added, never renamed), the per-sequence summary, and the
// results document both writers (this JSON one, core/report/results_csv.h) turn into a file.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/pipeline/pipeline.h"
#include "core/report/detection_record.h"

namespace tunnelmap {

// {"index","source","detected","status","reason","width_m","height_m","planes","walls":{...},
//  "axis":{...},"timings_ms":{...}}; walls are in the camera frame; unknown values are null.
nlohmann::json detection_record_json(const DetectionRecord& record);
inline nlohmann::json detection_frame_json(std::size_t index, const std::string& source, const FrameResult& result) {
  return detection_record_json(detection_record(static_cast<int>(index), source, result));
}

// {"index","source","planes":[{"id","normal","centroid","points","area_m2",...}],"timings_ms"}.
nlohmann::json planes_frame_json(std::size_t index, const std::string& source,
                                 const PlaneSegments& planes, const StageTimings& timings_ms);

// Mean and sample standard deviation (n - 1, core/report/statistics.h) of the width and height
// measured in the detected frames (the paper's mean(sigma)), plus errors against ground truth.
// Only measured values count (never the context's or the design's); width_frames and
// height_frames say how many frames each statistic covers; a statistic without values is
// unknown (empty, null in JSON), never 0.
struct DetectionSummary {
  int frames = 0;
  int detected = 0;
  int partial = 0;  // of the detected, frames with a wall out of view
  int width_frames = 0, height_frames = 0;  // frames that measured the width, the height
  std::optional<double> width_mean_m, width_std_m, height_mean_m, height_std_m;  // std: 2+ values
  std::optional<double> gt_width_m, gt_height_m;
  std::optional<double> width_abs_error_mean_m, height_abs_error_mean_m;  // with ground truth
  std::optional<double> total_ms_median;

  void add(const FrameResult& r) { add(detection_record(frames, {}, r)); }
  void add(const DetectionRecord& r);
  void finish();

 private:
  std::vector<double> widths_, heights_, totals_;
};
nlohmann::json summary_json(const DetectionSummary& summary);

// The summary of one method and parameter set when a document holds several (the GUI's rows).
struct GroupSummary {
  Method method = Method::Pgc;
  int param_set = 0;
  std::optional<Parameters> params;
  DetectionSummary summary;
};

// The whole document: {"tool","version","method","input","params","frames","summary"}, and
// "summaries" when the frames come from more than one method or parameter set (every frame then
// names its "param_set"; a frame of another method than the document's names its "method").
struct DetectionDocument {
  Method method = Method::Pgc;
  std::string input;
  Parameters params;
  std::vector<DetectionRecord> frames;
  DetectionSummary summary;
  std::vector<GroupSummary> summaries;  // empty: one group
};
nlohmann::json detection_document_json(const DetectionDocument& document);

// THE JSON writer of a results document (`detect --json`, the GUI's results export): two-space
// indented, one trailing newline, written atomically.
void write_detection_json(const std::string& path, const DetectionDocument& document);

}  // namespace tunnelmap
