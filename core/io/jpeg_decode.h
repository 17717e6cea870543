#pragma once
// JPEG decoding through libjpeg with the library's errors and warnings routed into the one
// message the tool prints: OpenCV's JPEG decoder lets libjpeg print "Corrupt JPEG data: …"
// lines on stderr before (or instead of) the tool's own message. A warning is a damaged image
// here (libjpeg would decode on and fill the rest with grey): the decode fails.
#include <cstdint>
#include <string>
#include <vector>

namespace tunnelmap {

// A colour (YCbCr or RGB, 3-component) JPEG as 8-bit RGB, row-major. InputError(path, ...):
// "corrupt JPEG: <libjpeg's reason>", a grey or CMYK image, or more than `max_pixels` pixels
// (checked from the frame header, before any row is decoded).
std::vector<std::uint8_t> decode_jpeg_rgb8(const std::vector<std::uint8_t>& bytes, const std::string& path,
                                           long long max_pixels, int& width, int& height);

}  // namespace tunnelmap
