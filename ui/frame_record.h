#pragma once
// One row of the results panel: what the pipeline reported for one frame.
#include <QString>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/baselines/method.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap::ui {

struct FrameRecord {
  int index = 0;
  Method method = Method::Pgc;
  bool detected = false;
  std::string status;
  double width_m = 0.0, height_m = 0.0;
  int planes = 0;
  StageTimings timings_ms;

  static FrameRecord from(int index, const FrameResult& r, Method method = Method::Pgc) {
    FrameRecord f;
    f.index = index;
    f.method = method;
    // A partial map with a dimension unknown has no width/height to tabulate or average.
    f.detected = r.map.has_width() && r.map.has_height();
    f.status = r.map.status;
    f.width_m = r.map.width_m;
    f.height_m = r.map.height_m;
    f.planes = static_cast<int>(r.planes.planes.size());
    f.timings_ms = r.timings_ms;
    return f;
  }
};

// Mean and standard deviation of width/height over the detected frames (paper, Table 1).
struct RunningStats {
  int detected = 0, frames = 0;
  double width_mean = 0, width_std = 0, height_mean = 0, height_std = 0;
};
RunningStats running_stats(const std::vector<FrameRecord>& records);

// Results files: JSON ("tunnelmap-results/1", loadable as a preset by its "params") and CSV.
void write_results_json(const std::string& path, const std::string& input,
                        const std::vector<FrameRecord>& records, const nlohmann::json& params);
void write_results_csv(const std::string& path, const std::vector<FrameRecord>& records);

}  // namespace tunnelmap::ui
