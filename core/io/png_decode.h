#pragma once
// PNG decoding through libpng with the library's own errors and warnings routed into the one
// message the tool prints: OpenCV's PNG decoder lets libpng print "libpng error: …" lines on
// stderr before the tool's own message. Both functions take the whole file in memory and
// throw InputError(path, "corrupt PNG: <libpng's reason>") on any decoding error.
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap {

// A 16-bit single-channel PNG (a depth image): width x height values, host byte order, no
// gamma or any other transformation.
std::vector<std::uint16_t> decode_png_grey16(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                             int& width, int& height);

// Any PNG as 8-bit RGB (palette and grey expanded, alpha dropped, 16-bit reduced).
std::vector<std::uint8_t> decode_png_rgb8(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                          int& width, int& height);

}  // namespace tunnelmap
