#include "core/recordings/rosbag2_metadata.h"

#include <sstream>

namespace tunnelmap::recordings {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string unquote(std::string s) {
  if (s.size() >= 2 && (s.front() == '\'' || s.front() == '"') && s.back() == s.front())
    s = s.substr(1, s.size() - 2);
  return s;
}

// "key: value" -> value, when the trimmed line starts with key (after an optional "- ").
bool value_of(const std::string& line, const std::string& key, std::string& value) {
  std::string t = trim(line);
  if (t.rfind("- ", 0) == 0) t = trim(t.substr(2));
  if (t.rfind(key + ":", 0) != 0) return false;
  value = unquote(trim(t.substr(key.size() + 1)));
  return true;
}

}  // namespace

Rosbag2Metadata parse_rosbag2_metadata(const std::string& yaml_text) {
  Rosbag2Metadata m;
  std::istringstream in(yaml_text);
  std::string line, value, last_name;
  bool in_files = false;
  while (std::getline(in, line)) {
    const std::string t = trim(line);
    if (in_files) {
      if (t.rfind("- ", 0) == 0) {
        m.relative_file_paths.push_back(unquote(trim(t.substr(2))));
        continue;
      }
      in_files = false;
    }
    if (value_of(line, "relative_file_paths", value)) in_files = value.empty();
    if (value_of(line, "name", value)) last_name = value;
    if (value_of(line, "serialization_format", value)) m.serialization_formats[last_name] = value;
  }
  return m;
}

}  // namespace tunnelmap::recordings
