#pragma once
// Markdown report of an evaluation: the paper's Table 1 layout (mean(sigma) in mm per cell and
// method), then errors against ground truth, detection rates, speed, segmentation quality and
// the acceptance bounds. Deterministic text except the timing columns.
#include <string>
#include <vector>

#include "core/evaluation/cell_result.h"
#include "core/evaluation/table1_bounds.h"

namespace tunnelmap {

struct ReportInfo {
  std::string title = "Table 1 reproduction";
  std::string protocol;  // one paragraph describing frames, seeds, options
};

std::string evaluation_markdown(const std::vector<CellResult>& results,
                                const std::vector<BoundCheck>& bounds, const ReportInfo& info);

}  // namespace tunnelmap
