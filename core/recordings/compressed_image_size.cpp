#include "core/recordings/compressed_image_size.h"

#include <cstring>

namespace tunnelmap::recordings {
namespace {

std::uint32_t big_endian(const std::uint8_t* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

// PNG: the signature, then the IHDR chunk whose data starts with width and height.
bool png_size(const std::uint8_t* d, std::size_t n, int& width, int& height) {
  static const std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (n < 24 || std::memcmp(d, kSignature, 8) != 0 || std::memcmp(d + 12, "IHDR", 4) != 0) return false;
  const std::uint32_t w = big_endian(d + 16, 4), h = big_endian(d + 20, 4);
  if (w == 0 || h == 0 || w > 0x7fffffffu || h > 0x7fffffffu) return false;
  width = static_cast<int>(w), height = static_cast<int>(h);
  return true;
}

// JPEG: markers after SOI up to the first start-of-frame (SOF0-SOF15 but DHT, JPG and DAC),
// whose data holds the precision, then height and width.
bool jpeg_size(const std::uint8_t* d, std::size_t n, int& width, int& height) {
  if (n < 4 || d[0] != 0xFF || d[1] != 0xD8) return false;
  std::size_t i = 2;
  while (i + 4 <= n) {
    if (d[i] != 0xFF) return false;
    const std::uint8_t marker = d[i + 1];
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    const std::size_t length = big_endian(d + i + 2, 2);
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (i + 9 > n || length < 7) return false;
      height = static_cast<int>(big_endian(d + i + 5, 2));
      width = static_cast<int>(big_endian(d + i + 7, 2));
      return width > 0 && height > 0;
    }
    if (length < 2) return false;
    i += 2 + length;
  }
  return false;
}

}  // namespace

bool compressed_image_size(const std::uint8_t* data, std::size_t size, int& width, int& height) {
  return data && (png_size(data, size, width, height) || jpeg_size(data, size, width, height));
}

}  // namespace tunnelmap::recordings
