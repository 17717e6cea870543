#include "core/io/pcd_header.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/io/depth_png.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

constexpr int kMaxHeaderLines = 64;
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr std::size_t kMaxFields = 256;
constexpr std::uint64_t kMaxFieldCount = 4096;  // e.g. a 308-bin VFH descriptor fits
// LZF never compresses better than about 1:100; a smaller compressed block is a lie.
constexpr std::uint64_t kMaxLzfRatio = 128;

std::uint64_t parse_count(const std::string& path, const std::string& key, std::istringstream& in) {
  long long v = -1;
  if (!(in >> v) || v < 0) throw InputError(path, "corrupt PCD header: bad " + key);
  return static_cast<std::uint64_t>(v);
}

// Numbers after SIZE / COUNT: each 1..max.
std::vector<std::uint64_t> parse_list(const std::string& path, const std::string& key, std::istringstream& in,
                                      std::uint64_t max) {
  std::vector<std::uint64_t> out;
  for (std::string w; in >> w;) {
    long long v = -1;
    std::istringstream one(w);
    if (!(one >> v) || !one.eof() || v < 1 || static_cast<std::uint64_t>(v) > max)
      throw InputError(path, "corrupt PCD header: bad " + key + " value '" + w.substr(0, 20) + "'");
    out.push_back(static_cast<std::uint64_t>(v));
  }
  return out;
}

// PCL reads a header line by line and stops at the first line whose first word is not one of
// its keywords (matched as prefixes), also after DATA. Lines that PCL would read differently
// from us are refused, so that PCL sees exactly the header we checked.
const char* const kPclKeywords[] = {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                    "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};

bool starts_with_pcl_keyword(const std::string& word) {
  for (const char* k : kPclKeywords)
    if (word.rfind(k, 0) == 0) return true;
  return false;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

// After DATA, PCL goes on reading "header" lines from the data: it skips empty lines and
// comments and would apply any keyword line it finds there. Such data is refused.
void check_data_start(const std::string& path, const std::string& head, std::size_t offset,
                      std::uintmax_t file_size) {
  for (std::size_t pos = offset; pos < head.size();) {
    const std::size_t nl = head.find('\n', pos);
    const std::string line = head.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? head.size() : nl + 1;
    if (line.empty()) continue;
    std::size_t b = 0;
    while (b < line.size() && is_space(line[b])) ++b;
    std::size_t e = b;
    while (e < line.size() && !is_space(line[e])) ++e;
    const std::string word = line.substr(b, e - b);
    if (!word.empty() && word[0] == '#') continue;  // a "comment": PCL reads on
    if (!starts_with_pcl_keyword(word)) return;     // PCL stops here: the data is read as data
    throw InputError(path, "corrupt PCD: the data after DATA starts with a header line ('" +
                               word.substr(0, 20) + "')");
  }
  if (head.size() < file_size)
    throw InputError(path, "corrupt PCD: no data within the first 64 KiB after DATA");
}

// PCL applies header lines in file order and acts on each at once: every POINTS line
// allocates POINTS x (the point size known so far), and SIZE / TYPE / COUNT build on the lines
// before them. A repeated keyword, or the field description after POINTS, would make PCL read
// (and allocate for) a header other than the one we checked: found by fuzzing, a first
// "POINTS 1500000000000008" made PCL request 18 PB. Such headers are refused.
void check_keyword_order(const std::string& path, const std::string& key, std::set<std::string>& seen) {
  if (key == "VERSION" || key == "VIEWPOINT" || key == "WIDTH" || key == "HEIGHT" || key == "POINTS" ||
      key == "FIELDS" || key == "SIZE" || key == "TYPE" || key == "COUNT") {
    if (!seen.insert(key).second)
      throw InputError(path, "corrupt PCD header: " + key + " appears more than once");
  }
  // Each of these needs the ones listed before it; POINTS needs the whole field description.
  const auto require = [&](const char* before) {
    if (!seen.count(before))
      throw InputError(path, "corrupt PCD header: " + key + " before " + before + " (PCL reads them in order)");
  };
  if (key == "SIZE") require("FIELDS");
  if (key == "TYPE") require("SIZE");
  if (key == "COUNT") require("TYPE");
  if (key == "POINTS") require("TYPE");
  if ((key == "FIELDS" || key == "SIZE" || key == "TYPE" || key == "COUNT") && seen.count("POINTS"))
    throw InputError(path, "corrupt PCD header: " + key + " after POINTS (PCL reads them in order)");
}

std::uint32_t little_u32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

}  // namespace

PcdHeader read_pcd_header(const std::string& path) {
  std::error_code ec;
  const auto file_size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read: " + ec.message());
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "cannot open for reading");
  // Only the first 64 KiB can hold the header: a file without newlines is not read whole.
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(file_size, kMaxHeaderBytes)), '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(file.gcount()));
  std::istringstream in(head);

  PcdHeader h;
  std::set<std::string> seen;
  bool have_width = false, have_height = false, have_points = false, have_count = false;
  std::string line;
  for (int n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
    if (in.eof()) break;  // a header line must end in a newline within the first 64 KiB
    if (line.empty()) continue;  // PCL skips these too
    if (line.back() == '\r') line.pop_back();
    // PCL would end its header at a blank line and split words differently on control bytes.
    if (line.empty() || is_space(line[0]) ||
        std::any_of(line.begin(), line.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\t'; }))
      throw InputError(path, "corrupt PCD header: blank, indented or binary line before DATA");
    if (line[0] == '#') continue;
    std::istringstream words(line);
    std::string key;
    words >> key;
    check_keyword_order(path, key, seen);
    if (key == "FIELDS") {
      for (std::string f; words >> f;) h.fields.push_back(f);
      if (h.fields.size() > kMaxFields) throw InputError(path, "corrupt PCD header: too many FIELDS");
    } else if (key == "SIZE") {
      h.sizes = parse_list(path, key, words, 8);
    } else if (key == "COUNT") {
      h.counts = parse_list(path, key, words, kMaxFieldCount);
      have_count = true;
    } else if (key == "TYPE") {
      for (std::string t; words >> t;) {
        if (t != "F" && t != "I" && t != "U")
          throw InputError(path, "corrupt PCD header: bad TYPE '" + t.substr(0, 20) + "' (F, I or U)");
        h.types.push_back(t[0]);
      }
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
    } else if (key != "VERSION" && key != "VIEWPOINT") {
      throw InputError(path, "is not a valid PCD file (unexpected header line '" +
                                 line.substr(0, 40) + "')");
    }
  }
  if (h.data.empty() || h.fields.empty() || !have_width)
    throw InputError(path, "is not a valid PCD file (incomplete header)");
  if (!have_count) h.counts.assign(h.fields.size(), 1);
  if (h.sizes.size() != h.fields.size() || h.types.size() != h.fields.size() ||
      h.counts.size() != h.fields.size())
    throw InputError(path, "corrupt PCD header: SIZE, TYPE and COUNT must have one entry per field (" +
                               std::to_string(h.fields.size()) + " FIELDS)");
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    const std::uint64_t s = h.sizes[i];
    if (s != 1 && s != 2 && s != 4 && s != 8)
      throw InputError(path, "corrupt PCD header: bad SIZE " + std::to_string(s) + " for field '" +
                                 h.fields[i].substr(0, 20) + "' (1, 2, 4 or 8)");
    if (h.types[i] == 'F' && s != 4 && s != 8)
      throw InputError(path, "corrupt PCD header: field '" + h.fields[i].substr(0, 20) + "' has TYPE " +
                                 h.types[i] + " with SIZE " + std::to_string(s));
  }
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
  std::uint64_t values_per_point = 0;
  for (std::size_t i = 0; i < h.sizes.size(); ++i) {
    h.point_step += h.sizes[i] * h.counts[i];
    values_per_point += h.counts[i];
  }
  if (h.data != "binary" && h.data != "ascii" && h.data != "binary_compressed")
    throw InputError(path, "is not a valid PCD file (unknown DATA type '" + h.data.substr(0, 20) + "')");
  // Every point needs at least point_step bytes (binary) or "v " per value (ascii).
  const std::uint64_t data_bytes = h.points * h.point_step;
  const std::uint64_t min_bytes = h.data == "binary"  ? data_bytes
                                  : h.data == "ascii" ? h.points * 2 * values_per_point - 1
                                                      : 8;
  check_data_start(path, head, static_cast<std::size_t>(h.data_offset), file_size);
  if (file_size < h.data_offset + min_bytes)
    throw InputError(path, "truncated PCD: too short for its " + std::to_string(h.points) + " points");
  if (h.data == "binary_compressed") {
    // Two little-endian uint32 (compressed, uncompressed size), then the LZF block. PCL sizes
    // its buffers from them, so they must agree with the header and the file first.
    char sizes[8];
    file.clear();
    file.seekg(static_cast<std::streamoff>(h.data_offset));
    if (!file.read(sizes, 8)) throw InputError(path, "truncated PCD: no compressed block");
    const std::uint64_t compressed = little_u32(sizes), uncompressed = little_u32(sizes + 4);
    if (uncompressed != data_bytes)
      throw InputError(path, "corrupt PCD: compressed block holds " + std::to_string(uncompressed) +
                                 " bytes, the header needs " + std::to_string(data_bytes));
    if (compressed == 0 || h.data_offset + 8 + compressed > file_size)
      throw InputError(path, "truncated PCD: compressed block of " + std::to_string(compressed) +
                                 " bytes runs past the end of the file");
    if (uncompressed > compressed * kMaxLzfRatio)
      throw InputError(path, "corrupt PCD: compressed block too small for " + std::to_string(h.points) + " points");
  }
  return h;
}

}  // namespace tunnelmap
