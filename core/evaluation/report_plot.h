#pragma once
// PNG plots of evaluation results, drawn with OpenCV imgproc (no Python, no gnuplot).
#include <string>
#include <vector>

#include "core/evaluation/cell_result.h"

namespace tunnelmap {

// table1.png: per experiment a panel of signed mean error (bar) and sigma (whisker) of width
// and height per cell and method. Bars beyond the axis range are clipped and marked.
void write_table1_plot(const std::string& path, const std::vector<CellResult>& results);

// sweeps.png: per sweep (experiment) two panels: mean |error| and detection rate versus the
// swept value, one line per method.
void write_sweeps_plot(const std::string& path, const std::vector<CellResult>& results);

}  // namespace tunnelmap
