#include "ui/frame_record.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/util/atomic_file.h"

namespace tunnelmap::ui {

RunningStats running_stats(const std::vector<FrameRecord>& records) {
  RunningStats s;
  s.frames = static_cast<int>(records.size());
  double sw = 0, sww = 0, sh = 0, shh = 0;
  for (const auto& r : records) {
    if (!r.detected) continue;
    ++s.detected;
    sw += r.width_m;
    sww += r.width_m * r.width_m;
    sh += r.height_m;
    shh += r.height_m * r.height_m;
  }
  if (s.detected == 0) return s;
  const double n = s.detected;
  s.width_mean = sw / n;
  s.height_mean = sh / n;
  // Sample standard deviation, as reported in the paper's table.
  if (s.detected > 1) {
    s.width_std = std::sqrt(std::max(0.0, (sww - n * s.width_mean * s.width_mean) / (n - 1)));
    s.height_std = std::sqrt(std::max(0.0, (shh - n * s.height_mean * s.height_mean) / (n - 1)));
  }
  return s;
}

void write_results_json(const std::string& path, const std::string& input,
                        const std::vector<FrameRecord>& records, const nlohmann::json& params) {
  nlohmann::json j;
  j["format"] = "tunnelmap-results/1";
  j["tool"] = "tunnelmap";
  j["version"] = TUNNELMAP_VERSION;
  j["input"] = input;
  j["params"] = params;
  j["frames"] = nlohmann::json::array();
  for (const auto& r : records)
    j["frames"].push_back({{"index", r.index}, {"method", method_name(r.method)}, {"detected", r.detected}, {"status", r.status},
                           {"width_m", r.width_m}, {"height_m", r.height_m}, {"planes", r.planes},
                           {"timings_ms", r.timings_ms}});
  const RunningStats s = running_stats(records);
  j["summary"] = {{"frames", s.frames},          {"detected", s.detected},
                  {"width_mean_m", s.width_mean}, {"width_std_m", s.width_std},
                  {"height_mean_m", s.height_mean}, {"height_std_m", s.height_std}};
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

void write_results_csv(const std::string& path, const std::vector<FrameRecord>& records) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "frame,detected,status,width_m,height_m,planes,total_ms,method\n";
    for (const auto& r : records) {
      auto t = r.timings_ms.find("total");
      out << r.index << ',' << (r.detected ? 1 : 0) << ',' << r.status << ',' << r.width_m << ','
          << r.height_m << ',' << r.planes << ',' << (t == r.timings_ms.end() ? 0.0 : t->second)
          << ',' << method_name(r.method) << "\n";
    }
  });
}

}  // namespace tunnelmap::ui
