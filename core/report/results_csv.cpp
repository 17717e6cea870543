#include "core/report/results_csv.h"

#include <locale>
#include <nlohmann/json.hpp>
#include <sstream>

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

// A value as the JSON document shows it: strings unquoted, null and missing empty.
void cell(std::ostream& out, const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return;
  if (it->is_string())
    text_cell(out, it->get<std::string>());
  else if (it->is_boolean())
    out << (it->get<bool>() ? 1 : 0);
  else
    out << it->dump();
}

}  // namespace

std::string detection_csv(const nlohmann::json& document) {
  static const char* const kColumns[] = {"index",        "source",        "method", "detected",
                                         "status",       "width_m",       "height_m",
                                         "width_source", "height_source", "planes", "total_ms",
                                         "reason"};
  std::ostringstream out;
  out.imbue(std::locale::classic());  // no digit grouping from a global locale
  for (const char* c : kColumns) out << (c == kColumns[0] ? "" : ",") << c;
  out << '\n';
  static const nlohmann::json kNone = nlohmann::json::object();
  const auto frames = document.find("frames");
  if (frames == document.end()) return out.str();
  for (const nlohmann::json& f : *frames) {
    const auto timings = f.find("timings_ms");
    for (const char* c : kColumns) {
      if (c != kColumns[0]) out << ',';
      const std::string key = c;
      if (key == "method")
        cell(out, f.contains("method") ? f : document, c);
      else if (key == "total_ms")
        cell(out, timings != f.end() ? *timings : kNone, "total");
      else
        cell(out, f, c);
    }
    out << '\n';
  }
  return out.str();
}

void write_detection_csv(const std::string& path, const nlohmann::json& document) {
  const std::string text = detection_csv(document);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace tunnelmap
