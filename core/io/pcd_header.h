#pragma once
// Our own reading of a PCD file's text header. PCL's readHeader already sizes the point buffer
// from WIDTH x HEIGHT, so a hostile header must be refused before PCL sees the file.
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap {

struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<std::uint64_t> sizes, counts;  // per field (COUNT defaults to 1)
  std::vector<char> types;                   // per field: 'F', 'I' or 'U'
  std::uint64_t width = 0, height = 0, points = 0;
  std::uint64_t point_step = 0;   // bytes per point (sum of SIZE x COUNT)
  std::string data;               // "ascii", "binary" or "binary_compressed"
  std::uint64_t data_offset = 0;  // byte offset of the data after the DATA line
};

// Throws InputError naming `path` for a missing file, a header that is not PCD (within its first
// 64 KiB), SIZE/TYPE/COUNT that do not match FIELDS, sizes that are 0 or above kMaxImageSide,
// POINTS != WIDTH x HEIGHT, a file too short for its points, or a binary_compressed block
// whose sizes disagree with the header or the file.
PcdHeader read_pcd_header(const std::string& path);

}  // namespace tunnelmap
