#pragma once
// One row of the results panel: core's DetectionRecord of a frame (with its method and
// parameter set), and the results document of the rows, the model `detect --json/--csv` writes.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/io/dataset.h"
#include "core/report/results_json.h"

namespace tunnelmap::ui {

using FrameRecord = DetectionRecord;

// The summary `detect` prints for these rows (core/report/results_json.h: the width and height
// measured in the detected frames, never inferred ones; sample sigma; errors against the ground
// truth when given).
DetectionSummary summary_of(const std::vector<FrameRecord>& records, std::optional<double> gt_width_m = {},
                            std::optional<double> gt_height_m = {});

// The results document of the rows, as `detect --json` writes it for the same frames. Rows of
// different methods or parameter sets never share a summary: "method", "params" and "summary"
// are those of the main group — the rows made with `params` (the current parameters,
// recognised through `set_params(k)`, the parameters of set k), else the first row's method and
// set. With more than one group every row carries its "param_set" and "summaries" lists each
// group's method, set, parameters and summary. `dataset` (may be null) gives the ground truth.
DetectionDocument results_document(const std::vector<FrameRecord>& records, const Parameters& params,
                                   const std::string& input, const Dataset* dataset,
                                   const std::function<std::optional<Parameters>(int set)>& set_params = {});

}  // namespace tunnelmap::ui
