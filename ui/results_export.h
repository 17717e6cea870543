#pragma once
// Results files of the GUI, one entry per results-table row: the documents `detect --json` and
// `--csv` write (core/report; the JSON loads as a preset by its "params"). The File-menu
// exports (MainWindow::export_*) are in results_export.cpp too.
#include <functional>
#include <string>
#include <vector>

#include "ui/frame_record.h"

namespace tunnelmap::ui {

// `dataset` (may be null): the ground truth of the summary.
// `set_params(k)`: the parameters of set k (results_document).
void write_results_json(const std::string& path, const std::string& input,
                        const std::vector<FrameRecord>& records, const Parameters& params,
                        const Dataset* dataset,
                        const std::function<std::optional<Parameters>(int)>& set_params = {});
void write_results_csv(const std::string& path, const std::vector<FrameRecord>& records);

}  // namespace tunnelmap::ui
