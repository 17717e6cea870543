#include "core/report/results_csv.h"

#include <locale>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/report/json_numbers.h"
#include "core/util/atomic_file.h"

namespace tunnelmap {

namespace {

void text_cell(std::ostream& out, const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) {
    out << s;
    return;
  }
  out << '"';
  for (char c : s) out << (c == '"' ? "\"\"" : std::string(1, c));
  out << '"';
}

// A number as the JSON document writes it (same rounding, same shortest form); unknown: empty.
void number_cell(std::ostream& out, const std::optional<double>& v, double unit) {
  if (v) out << nlohmann::json(round_to(*v, unit)).dump();
}

void source_cell(std::ostream& out, const std::optional<DimensionSource>& s) {
  if (s) out << dimension_source_name(*s);
}

}  // namespace

std::string detection_csv(const DetectionDocument& document) {
  std::ostringstream out;
  out.imbue(std::locale::classic());  // no digit grouping from a global locale
  out << "index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,total_ms,reason\n";
  for (const DetectionRecord& r : document.frames) {
    out << r.index << ',';
    text_cell(out, r.source);
    out << ',' << method_name(r.method) << ',' << (r.detected ? 1 : 0) << ',';
    text_cell(out, r.status);
    out << ',';
    number_cell(out, r.width_m, 1e-5);
    out << ',';
    number_cell(out, r.height_m, 1e-5);
    out << ',';
    source_cell(out, r.width_source);
    out << ',';
    source_cell(out, r.height_source);
    out << ',';
    if (!r.error) out << r.planes;
    out << ',';
    number_cell(out, r.total_ms(), 1e-3);
    out << ',';
    text_cell(out, r.reason);
    out << '\n';
  }
  return out.str();
}

void write_detection_csv(const std::string& path, const DetectionDocument& document) {
  const std::string text = detection_csv(document);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace tunnelmap
