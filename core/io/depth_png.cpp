#include "core/io/depth_png.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/jpeg_decode.h"
#include "core/io/png_decode.h"
#include "core/util/error.h"

namespace tunnelmap {
namespace fs = std::filesystem;

namespace {

// Before decoding: a small file can claim a frame that takes gigabytes once decoded.
void check_image_pixels(const std::string& path, int w, int h, long long max_pixels) {
  if (static_cast<long long>(w) * h <= max_pixels) return;
  char mpx[32];
  std::snprintf(mpx, sizeof mpx, "%.1f", static_cast<double>(max_pixels) / 1e6);
  throw InputError(path, "image of " + std::to_string(w) + "x" + std::to_string(h) + " pixels is too large (at most " +
                             std::to_string(max_pixels) + " = " + mpx + " Mpx, input.max_image_pixels)");
}

constexpr std::size_t kMaxImageFileBytes = 512u << 20;
const std::uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t big_endian_u32(const std::uint8_t* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
         std::uint32_t(p[3]);
}

std::string describe_png_type(const PngHeader& h) {
  static const char* names[] = {"grey", "?", "RGB", "palette", "grey+alpha", "?", "RGBA"};
  const char* name = (h.colour_type >= 0 && h.colour_type <= 6) ? names[h.colour_type] : "?";
  return std::to_string(h.bit_depth) + "-bit " + name;
}

// The size in a JPEG's frame header (SOFn), read before libjpeg allocates anything: walk the
// marker segments up to the first SOFn; InputError if there is none before the scan.
void check_jpeg_size(const std::vector<std::uint8_t>& b, const std::string& path, long long max_pixels) {
  std::size_t pos = 2;  // after SOI (FF D8)
  while (pos + 4 <= b.size()) {
    if (b[pos] != 0xff) break;
    const std::uint8_t marker = b[pos + 1];
    if (marker == 0xff) {  // fill byte
      ++pos;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {  // no length
      pos += 2;
      continue;
    }
    if (marker == 0xda || marker == 0xd9) break;  // scan or end before any frame header
    const std::size_t length = (std::size_t(b[pos + 2]) << 8) | b[pos + 3];
    const bool sof = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc;
    if (sof) {
      if (length < 7 || pos + 9 > b.size()) break;
      const int h = (b[pos + 5] << 8) | b[pos + 6], w = (b[pos + 7] << 8) | b[pos + 8];
      if (w == 0 || h == 0 || w > kMaxImageSide || h > kMaxImageSide)
        throw InputError(path, "absurd image size " + std::to_string(w) + "x" + std::to_string(h) +
                                   " (each side must be 1.." + std::to_string(kMaxImageSide) + ")");
      check_image_pixels(path, w, h, max_pixels);
      return;
    }
    if (length < 2) break;
    pos += 2 + length;
  }
  throw InputError(path, "corrupt JPEG: no frame header");
}

// Decodes an in-memory image, keeping its bit depth and channel count.
cv::Mat decode(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  cv::Mat img;
  try {
    img = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1,
                               const_cast<std::uint8_t*>(bytes.data())),
                       cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  } catch (const cv::Exception& e) {
    throw InputError(path, "cannot decode the image (corrupt or truncated)");
  }
  if (img.empty()) throw InputError(path, "cannot decode the image (corrupt or truncated)");
  return img;
}

// A truncated PNG can decode "successfully" with missing rows: walk the chunk list and
// require every chunk to be complete up to IEND.
void require_png_end(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  std::size_t pos = 8;
  while (pos + 12 <= bytes.size()) {
    const std::size_t length = big_endian_u32(bytes.data() + pos);
    const bool is_end = std::memcmp(bytes.data() + pos + 4, "IEND", 4) == 0;
    if (length > bytes.size() - pos - 12) break;  // chunk runs past the end of the file
    if (is_end) return;
    pos += 12 + length;
  }
  throw InputError(path, "truncated or corrupt PNG (ends before its IEND chunk)");
}

}  // namespace

std::vector<std::uint8_t> read_file_bytes(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, ec ? "cannot access: " + ec.message() : "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a folder, expected a file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw InputError(path, "cannot read: " + ec.message());
  if (size > max_bytes)
    throw InputError(path, "file is too large (" + std::to_string(size) + " bytes)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open for reading");
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  if (size > 0) in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
  if (!in) throw InputError(path, "read error");
  return bytes;
}

PngHeader parse_png_header(const std::vector<std::uint8_t>& bytes, const std::string& path, long long max_pixels) {
  // Signature (8) + IHDR length (4) + "IHDR" (4) + width (4) + height (4) + depth + colour type.
  if (bytes.size() < 26 || std::memcmp(bytes.data(), kPngSignature, 8) != 0)
    throw InputError(path, "is not a PNG file");
  if (std::memcmp(bytes.data() + 12, "IHDR", 4) != 0)
    throw InputError(path, "corrupt PNG: first chunk is not IHDR");
  const std::uint32_t w = big_endian_u32(bytes.data() + 16);
  const std::uint32_t h = big_endian_u32(bytes.data() + 20);
  if (w == 0 || h == 0 || w > std::uint32_t(kMaxImageSide) || h > std::uint32_t(kMaxImageSide))
    throw InputError(path, "absurd image size " + std::to_string(w) + "x" + std::to_string(h) +
                               " (each side must be 1.." + std::to_string(kMaxImageSide) + ")");
  check_image_pixels(path, static_cast<int>(w), static_cast<int>(h), max_pixels);
  PngHeader header;
  header.width = static_cast<int>(w);
  header.height = static_cast<int>(h);
  header.bit_depth = bytes[24];
  header.colour_type = bytes[25];
  return header;
}

DepthFrame read_depth_png(const std::string& path, const ReadOptions& opt) {
  return decode_depth_png(read_file_bytes(path, kMaxImageFileBytes), path, opt);
}

DepthFrame decode_depth_png(const std::vector<std::uint8_t>& bytes, const std::string& path,
                            const ReadOptions& opt) {
  const PngHeader header = parse_png_header(bytes, path, opt.max_image_pixels);
  if (header.bit_depth != 16 || header.colour_type != 0)
    throw InputError(path, std::string(header.bit_depth == 8 ? "is an " : "is a ") +
                               describe_png_type(header) +
                               " image; depth PNGs must be 16-bit single channel");
  require_png_end(bytes, path);
  DepthFrame f;
  const std::vector<std::uint16_t> raw = decode_png_grey16(bytes, path, f.width, f.height);
  if (f.width != header.width || f.height != header.height)
    throw InputError(path, "corrupt PNG: decoded size differs from its header");
  f.depth.assign(raw.begin(), raw.end());
  f.depth_units_per_m = opt.depth_units_per_m;
  f.intrinsics = intrinsics_for_image(opt, f.width, f.height);
  f.source = path;
  return f;
}

std::vector<std::uint8_t> read_rgb_image(const std::string& path, int& width, int& height, long long max_pixels) {
  return decode_rgb_image(read_file_bytes(path, kMaxImageFileBytes), path, width, height, max_pixels);
}

std::vector<std::uint8_t> decode_rgb_image(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                           int& width, int& height, long long max_pixels) {
  const bool is_png = bytes.size() >= 8 && std::memcmp(bytes.data(), kPngSignature, 8) == 0;
  const bool is_jpeg = bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff;
  // Only the two formats datasets use: OpenCV's other decoders (TIFF, EXR, ...) stay unreachable.
  if (!is_png && !is_jpeg) throw InputError(path, "is neither a PNG nor a JPEG image");
  if (is_png) {
    const PngHeader header = parse_png_header(bytes, path, max_pixels);
    const bool rgb = (header.colour_type == 2 && header.bit_depth == 8) || header.colour_type == 3;  // or a palette
    if (!rgb) throw InputError(path, "RGB images must be 8-bit 3-channel colour (" + describe_png_type(header) + ")");
    require_png_end(bytes, path);
    return decode_png_rgb8(bytes, path, width, height);
  }
  check_jpeg_size(bytes, path, max_pixels);
  return decode_jpeg_rgb8(bytes, path, max_pixels, width, height);
}

std::vector<std::uint16_t> read_label_png(const std::string& path, int& width, int& height, long long max_pixels) {
  return decode_label_png(read_file_bytes(path, kMaxImageFileBytes), path, width, height, max_pixels);
}

std::vector<std::uint16_t> decode_label_png(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                            int& width, int& height, long long max_pixels) {
  const PngHeader header = parse_png_header(bytes, path, max_pixels);
  require_png_end(bytes, path);
  const cv::Mat img = decode(bytes, path);
  if (img.channels() != 1)
    throw InputError(path, "label PNGs must be single channel (" + describe_png_type(header) + ")");
  cv::Mat img16;
  img.convertTo(img16, CV_16U);
  width = img16.cols;
  height = img16.rows;
  std::vector<std::uint16_t> out(static_cast<std::size_t>(width) * height);
  for (int v = 0; v < height; ++v)
    std::memcpy(out.data() + static_cast<std::size_t>(v) * width, img16.ptr(v),
                static_cast<std::size_t>(width) * 2);
  return out;
}

}  // namespace tunnelmap
