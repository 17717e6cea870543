#include "core/evaluation/report_csv.h"

#include <cstdio>
#include <sstream>

namespace tunnelmap {

namespace {
std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
std::string num(double v, const char* fmt = "%.3f") {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}
}  // namespace

std::string evaluation_csv(const std::vector<CellResult>& rs) {
  std::ostringstream out;
  out << "experiment,cell,cell_value,method,frames,detected,detection_rate,gt_width_mm,gt_height_mm,"
         "width_mean_mm,width_sd_mm,height_mean_mm,height_sd_mm,width_abs_err_mm,height_abs_err_mm,"
         "ms_per_frame,fps,planes,planes_correct,precision,surfaces,surfaces_found,recall\n";
  for (const CellResult& r : rs) {
    const bool det = r.detected > 0;
    out << quoted(r.experiment) << "," << quoted(r.cell) << "," << num(r.cell_value, "%g") << ","
        << method_name(r.method) << "," << r.frames << "," << r.detected << ","
        << num(r.detection_rate(), "%.4f") << ","
        << (r.gt_width_m ? num(*r.gt_width_m * 1000, "%.1f") : "") << ","
        << (r.gt_height_m ? num(*r.gt_height_m * 1000, "%.1f") : "") << ","
        << (det ? num(r.width_mean_m * 1000, "%.2f") : "") << ","
        << (det ? num(r.width_std_m * 1000, "%.2f") : "") << ","
        << (det ? num(r.height_mean_m * 1000, "%.2f") : "") << ","
        << (det ? num(r.height_std_m * 1000, "%.2f") : "") << ","
        << (det && r.gt_width_m ? num(r.width_abs_error_m * 1000, "%.2f") : "") << ","
        << (det && r.gt_height_m ? num(r.height_abs_error_m * 1000, "%.2f") : "") << ","
        << num(r.ms_mean, "%.2f") << "," << num(r.fps(), "%.3f") << ",";
    if (r.has_segmentation)
      out << r.segmentation.planes << "," << r.segmentation.correct_planes << ","
          << num(r.segmentation.precision(), "%.4f") << "," << r.segmentation.surfaces << ","
          << r.segmentation.found_surfaces << "," << num(r.segmentation.recall(), "%.4f");
    else
      out << ",,,,,";
    out << "\n";
  }
  return out.str();
}

}  // namespace tunnelmap
