#pragma once
// Reader for 16-bit single-channel depth PNGs (e.g. millimetres, 0 = no measurement).
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/io/read_options.h"

namespace tunnelmap {

// Largest accepted image side; anything bigger is refused before decoding.
constexpr int kMaxImageSide = 8192;

struct PngHeader {
  int width = 0;
  int height = 0;
  int bit_depth = 0;
  int colour_type = 0;  // 0 grey, 2 RGB, 3 palette, 4 grey+alpha, 6 RGBA
};

// Parses the signature and IHDR chunk of an in-memory PNG; throws InputError (naming `path`)
// if it is not a PNG, a side is 0 or larger than kMaxImageSide, or it has more than
// `max_pixels` pixels (ReadOptions::max_image_pixels).
PngHeader parse_png_header(const std::vector<std::uint8_t>& bytes, const std::string& path, long long max_pixels);

// Reads a whole file into memory; throws InputError if missing, unreadable or over `max_bytes`.
std::vector<std::uint8_t> read_file_bytes(const std::string& path, std::size_t max_bytes);

// Depth stays in file units: depth_units_per_m = opt.depth_units_per_m. Intrinsics from `opt`,
// else PrimeSense VGA scaled to the image size. `source` = path.
DepthFrame read_depth_png(const std::string& path, const ReadOptions& opt);

// The same from the file's bytes (the fuzzer's entry point); `path` is named in errors.
DepthFrame decode_depth_png(const std::vector<std::uint8_t>& bytes, const std::string& path,
                            const ReadOptions& opt);

// Reads an 8-bit colour PNG/JPEG as RGB8 row-major; throws InputError otherwise (also for
// more than `max_pixels` pixels, before decoding).
std::vector<std::uint8_t> read_rgb_image(const std::string& path, int& width, int& height, long long max_pixels);
std::vector<std::uint8_t> decode_rgb_image(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                           int& width, int& height, long long max_pixels);

// Reads a 16-bit single-channel label PNG (e.g. ground-truth surface ids).
std::vector<std::uint16_t> read_label_png(const std::string& path, int& width, int& height, long long max_pixels);
std::vector<std::uint16_t> decode_label_png(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                            int& width, int& height, long long max_pixels);

}  // namespace tunnelmap
