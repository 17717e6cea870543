#include "core/io/json_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/util/error.h"

namespace tunnelmap {

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
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {  // parse_error, but also out_of_range (overflow)
    std::string msg = e.what();
    for (char& ch : msg)
      if (ch == '\n' || ch == '\r') ch = ' ';
    throw InputError(path, "malformed JSON: " + msg);
  }
}

}  // namespace tunnelmap
