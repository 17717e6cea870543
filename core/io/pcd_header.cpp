#include "core/io/pcd_header.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/depth_png.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

constexpr int kMaxHeaderLines = 64;

std::uint64_t parse_count(const std::string& path, const std::string& key, std::istringstream& in) {
  long long v = -1;
  if (!(in >> v) || v < 0) throw InputError(path, "corrupt PCD header: bad " + key);
  return static_cast<std::uint64_t>(v);
}

}  // namespace

PcdHeader read_pcd_header(const std::string& path) {
  std::error_code ec;
  const auto file_size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read: " + ec.message());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open for reading");

  PcdHeader h;
  std::vector<std::uint64_t> sizes, counts;
  bool have_width = false, have_height = false, have_points = false;
  std::string line;
  for (int n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "FIELDS") {
      for (std::string f; words >> f;) h.fields.push_back(f);
    } else if (key == "SIZE") {
      for (long long s; words >> s;) sizes.push_back(static_cast<std::uint64_t>(s < 0 ? 0 : s));
    } else if (key == "COUNT") {
      for (long long c; words >> c;) counts.push_back(static_cast<std::uint64_t>(c < 0 ? 0 : c));
    } else if (key == "WIDTH") {
      h.width = parse_count(path, key, words);
      have_width = true;
    } else if (key == "HEIGHT") {
      h.height = parse_count(path, key, words);
      have_height = true;
    } else if (key == "POINTS") {
      h.points = parse_count(path, key, words);
      have_points = true;
    } else if (key == "DATA") {
      words >> h.data;
      h.data_offset = static_cast<std::uint64_t>(in.tellg());
      break;
    } else if (key != "VERSION" && key != "TYPE" && key != "VIEWPOINT") {
      throw InputError(path, "is not a valid PCD file (unexpected header line '" +
                                 line.substr(0, 40) + "')");
    }
  }
  if (h.data.empty() || h.fields.empty() || !have_width)
    throw InputError(path, "is not a valid PCD file (incomplete header)");
  if (!have_height) h.height = 1;
  if (!have_points) h.points = h.width * h.height;
  if (h.width == 0 || h.height == 0 || h.width > std::uint64_t(kMaxImageSide) ||
      h.height > std::uint64_t(kMaxImageSide))
    throw InputError(path, "absurd cloud size " + std::to_string(h.width) + "x" +
                               std::to_string(h.height) + " (each side must be 1.." +
                               std::to_string(kMaxImageSide) + ")");
  if (h.points != h.width * h.height)
    throw InputError(path, "corrupt PCD header: POINTS " + std::to_string(h.points) +
                               " differs from WIDTH x HEIGHT");
  for (std::size_t i = 0; i < sizes.size(); ++i) h.point_step += sizes[i] * (i < counts.size() ? counts[i] : 1);
  // Every point needs at least point_step bytes (binary) or "v " per field (ascii).
  const std::uint64_t min_bytes = h.data == "binary" ? h.points * h.point_step
                                  : h.data == "ascii" ? h.points * 2 * h.fields.size()
                                                      : 0;
  if (h.data != "binary" && h.data != "ascii" && h.data != "binary_compressed")
    throw InputError(path, "is not a valid PCD file (unknown DATA type '" + h.data + "')");
  if (file_size < h.data_offset + min_bytes)
    throw InputError(path, "truncated PCD: too short for its " + std::to_string(h.points) + " points");
  return h;
}

}  // namespace tunnelmap
