#pragma once
// results.csv: one row per (experiment, cell, method), lengths in millimetres, for
// spreadsheets and for the sweeps' plots.
#include <string>
#include <vector>

#include "core/evaluation/cell_result.h"

namespace tunnelmap {

// Header: experiment,cell,cell_value,method,frames,detected,detection_rate,gt_width_mm,
// gt_height_mm,width_mean_mm,width_sd_mm,height_mean_mm,height_sd_mm,width_abs_err_mm,
// height_abs_err_mm,ms_per_frame,fps,planes,planes_correct,precision,surfaces,surfaces_found,recall
std::string evaluation_csv(const std::vector<CellResult>& results);

}  // namespace tunnelmap
