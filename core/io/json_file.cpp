#include "core/io/json_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/util/error.h"

namespace tunnelmap {

namespace {
// Brackets outside strings, counted in one pass. (nlohmann's parser callback could stop deep
// input too, but with a callback its DOM builder rescans each array as it closes: a dataset of
// a million frames then takes minutes.)
bool nests_deeper_than(const std::string& text, int max_depth) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char ch : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (ch == '\\') escaped = true;
      else if (ch == '"') in_string = false;
    } else if (ch == '"') {
      in_string = true;
    } else if (ch == '[' || ch == '{') {
      if (++depth > max_depth) return true;
    } else if (ch == ']' || ch == '}') {
      --depth;
    }
  }
  return false;
}
}  // namespace

nlohmann::json read_json_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, ec ? "cannot access: " + ec.message() : "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a folder, expected a JSON file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read: " + ec.message());
  if (size > kMaxJsonFileBytes) throw InputError(path, "file is too large for a JSON file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open for reading");
  std::stringstream text;
  text << in.rdbuf();
  try {
    if (nests_deeper_than(text.str(), kMaxJsonDepth))
      throw InputError(path, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {  // parse_error, but also out_of_range (overflow)
    std::string msg = e.what();
    for (char& ch : msg)
      if (ch == '\n' || ch == '\r') ch = ' ';
    throw InputError(path, "malformed JSON: " + msg);
  }
}

}  // namespace tunnelmap
