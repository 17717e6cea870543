#pragma once
// One row of the results panel: what the pipeline reported for one frame, and that frame's
// entry of a results document (the model `detect --json/--csv` writes, core/report).
#include <QString>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/baselines/method.h"
#include "core/io/dataset.h"
#include "core/pipeline/pipeline.h"
#include "core/report/results_json.h"

namespace tunnelmap::ui {

struct FrameRecord {
  int index = 0;
  Method method = Method::Pgc;
  int param_set = 0;  // which parameter set made it (ResultsPanel numbers them from 1); 0 = unknown
  bool detected = false;  // width and height both known (measured or inferred)
  std::string status;     // status_name(), or "error" when the frame could not be read
  double width_m = 0.0, height_m = 0.0;
  int planes = 0;
  StageTimings timings_ms;
  nlohmann::json result;  // detection_frame_json(); null for an error row
  SummaryEntry summary;   // what DetectionSummary takes of the frame

  // `source`: the frame's file, as `detect --json` names it.
  static FrameRecord from(int index, const FrameResult& r, Method method = Method::Pgc,
                          const std::string& source = {});
};

// The summary `detect` prints for these rows (core/report/results_json.h: the width and height
// measured in the detected frames, never inferred ones; sample sigma; errors against the ground
// truth when given).
DetectionSummary summary_of(const std::vector<FrameRecord>& records, std::optional<double> gt_width_m = {},
                            std::optional<double> gt_height_m = {});

// The results document of the rows, as `detect --json` writes it for the same frames:
// detection_document() with the rows' frame objects and summary. Rows of different methods or
// parameter sets never share a summary: "method", "params" and "summary" are those of the main
// group — the rows made with `params` (the current parameters, recognised through
// `set_params(k)`, the parameters of set k), else the first row's method and set. A row of
// another method carries its own "method"; with more than one group every row carries its
// "param_set" and "summaries" lists each group's method, set, parameters and summary.
// `dataset` (may be null) gives the ground truth of the summaries.
nlohmann::json results_document(const std::vector<FrameRecord>& records, const nlohmann::json& params,
                                const std::string& input, const Dataset* dataset,
                                const std::function<nlohmann::json(int set)>& set_params = {});

}  // namespace tunnelmap::ui
