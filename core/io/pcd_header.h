#pragma once
// Our own reading of a PCD file's text header. PCL's readHeader already sizes the point buffer
// from WIDTH x HEIGHT, so a hostile header must be refused before PCL sees the file.
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap {

struct PcdHeader {
  std::vector<std::string> fields;
  std::uint64_t width = 0, height = 0, points = 0;
  std::uint64_t point_step = 0;   // bytes per point (sum of SIZE x COUNT)
  std::string data;               // "ascii", "binary" or "binary_compressed"
  std::uint64_t data_offset = 0;  // byte offset of the data after the DATA line
};

// Throws InputError naming `path` for a missing file, a header that is not PCD, sizes that are
// 0 or above kMaxImageSide, POINTS != WIDTH x HEIGHT, or a file too short for its points.
PcdHeader read_pcd_header(const std::string& path);

}  // namespace tunnelmap
