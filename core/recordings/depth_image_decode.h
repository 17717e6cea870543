#pragma once
// sensor_msgs/Image and CompressedImage messages as depth or colour pixels. Every size is
// checked against the data actually present: an inconsistent image is refused (TruncatedData
// with the reason; the caller names the topic and time).
#include <cstdint>
#include <string>
#include <vector>

#include "core/recordings/ros_messages.h"

namespace tunnelmap::recordings {

struct DecodedDepth {
  int width = 0, height = 0;
  std::vector<float> depth;         // row-major
  double depth_units_per_m = 1000;  // 1000 for 16UC1 (mm), 1 for 32FC1 (m)
};

DecodedDepth decode_depth_image(const RosImage& img);
// image_transport's compressedDepth: a 12-byte header (format, two inverse-depth quantisation
// parameters) then a PNG of 16UC1 depth or of quantised inverse 32FC1 depth. Compressed
// images that declare more than `max_pixels` pixels are refused before they are decoded.
DecodedDepth decode_compressed_depth(const RosCompressedImage& img, long long max_pixels);

// RGB8 row-major; width/height set.
std::vector<std::uint8_t> decode_color_image(const RosImage& img, int& width, int& height);
std::vector<std::uint8_t> decode_compressed_color(const RosCompressedImage& img, long long max_pixels, int& width,
                                                  int& height);

}  // namespace tunnelmap::recordings
