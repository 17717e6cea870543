#include "core/recordings/depth_image_decode.h"

#include <algorithm>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/compressed_image_size.h"

namespace tunnelmap::recordings {
namespace {

// Refuses an Image whose declared size and step do not fit its data.
void check_layout(const RosImage& img, std::size_t bytes_per_pixel) {
  const std::uint64_t row = static_cast<std::uint64_t>(img.width) * bytes_per_pixel;
  const std::uint64_t needed = static_cast<std::uint64_t>(img.step) * img.height;
  if (img.width == 0 || img.height == 0 || img.width > 100000 || img.height > 100000)
    throw TruncatedData("Image has size " + std::to_string(img.width) + "x" + std::to_string(img.height));
  if (img.step < row || img.size < needed)
    throw TruncatedData("Image " + std::to_string(img.width) + "x" + std::to_string(img.height) + " " +
                        img.encoding + " with step " + std::to_string(img.step) + " holds " +
                        std::to_string(img.size) + " data bytes, needs " + std::to_string(needed));
}

template <typename T>
T load_pixel(const std::uint8_t* p, bool swap) {
  std::uint8_t b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return v;
}

template <typename T>
void copy_plane(const RosImage& img, std::vector<float>& out) {
  out.resize(static_cast<std::size_t>(img.width) * img.height);
  for (std::uint32_t v = 0; v < img.height; ++v) {
    const std::uint8_t* row = img.data + static_cast<std::size_t>(v) * img.step;
    for (std::uint32_t u = 0; u < img.width; ++u)
      out[static_cast<std::size_t>(v) * img.width + u] =
          static_cast<float>(load_pixel<T>(row + u * sizeof(T), img.big_endian));
  }
}

// PNG or JPEG bytes, refused before decoding when they are neither or declare more than
// `max_pixels` pixels.
cv::Mat decode_png_bytes(const std::uint8_t* data, std::size_t size, int flags, long long max_pixels) {
  if (size == 0) throw TruncatedData("empty compressed image");
  int width = 0, height = 0;
  if (!compressed_image_size(data, size, width, height))
    throw TruncatedData("compressed image is neither a PNG nor a JPEG");
  if (static_cast<long long>(width) * height > max_pixels)
    throw TruncatedData("compressed image of " + std::to_string(width) + "x" + std::to_string(height) +
                        " pixels is over input.max_image_pixels = " + std::to_string(max_pixels));
  const cv::Mat bytes(1, static_cast<int>(size), CV_8UC1, const_cast<std::uint8_t*>(data));
  cv::Mat m = cv::imdecode(bytes, flags);
  if (m.empty()) throw TruncatedData("compressed image does not decode");
  return m;
}

std::vector<std::uint8_t> rgb_from_mat(const cv::Mat& m, int code) {
  cv::Mat rgb;
  if (code < 0)
    rgb = m;
  else
    cv::cvtColor(m, rgb, code);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(rgb.total()) * 3);
  for (int v = 0; v < rgb.rows; ++v) std::memcpy(&out[static_cast<std::size_t>(v) * rgb.cols * 3], rgb.ptr(v), rgb.cols * 3);
  return out;
}

}  // namespace

DecodedDepth decode_depth_image(const RosImage& img) {
  DecodedDepth d;
  if (img.encoding == "16UC1" || img.encoding == "mono16") {
    check_layout(img, 2);
    copy_plane<std::uint16_t>(img, d.depth);
    d.depth_units_per_m = 1000.0;  // REP 118: 16-bit depth in millimetres
  } else if (img.encoding == "32FC1") {
    check_layout(img, 4);
    copy_plane<float>(img, d.depth);
    d.depth_units_per_m = 1.0;  // metres
  } else {
    throw TruncatedData("Image encoding '" + img.encoding + "' is not a depth encoding (16UC1, 32FC1)");
  }
  d.width = static_cast<int>(img.width);
  d.height = static_cast<int>(img.height);
  return d;
}

DecodedDepth decode_compressed_depth(const RosCompressedImage& img, long long max_pixels) {
  if (img.format.find("compressedDepth") == std::string::npos)
    throw TruncatedData("CompressedImage format '" + img.format + "' is not compressedDepth");
  if (img.format.find("rvl") != std::string::npos)
    throw TruncatedData("compressedDepth RVL is not supported (only PNG)");
  ByteCursor header(img.data, img.size);
  header.u32();  // compression format
  const float quant_a = header.read<float>(), quant_b = header.read<float>();
  const cv::Mat png = decode_png_bytes(img.data + 12, img.size - 12, cv::IMREAD_UNCHANGED, max_pixels);
  if (png.type() != CV_16UC1) throw TruncatedData("compressedDepth PNG is not 16-bit single channel");
  DecodedDepth d;
  d.width = png.cols;
  d.height = png.rows;
  d.depth.resize(png.total());
  const bool inverse = img.format.rfind("32FC1", 0) == 0;
  d.depth_units_per_m = inverse ? 1.0 : 1000.0;
  for (int v = 0; v < png.rows; ++v)
    for (int u = 0; u < png.cols; ++u) {
      const std::uint16_t q = png.at<std::uint16_t>(v, u);
      // 32FC1 is stored as quantised inverse depth: depth = a / (q - b), 0 = no measurement.
      d.depth[static_cast<std::size_t>(v) * png.cols + u] =
          !inverse ? static_cast<float>(q) : q == 0 ? 0.0f : quant_a / (static_cast<float>(q) - quant_b);
    }
  return d;
}

std::vector<std::uint8_t> decode_color_image(const RosImage& img, int& width, int& height) {
  const std::string& e = img.encoding;
  const int channels = e == "mono8" ? 1 : (e == "rgba8" || e == "bgra8") ? 4 : (e == "rgb8" || e == "bgr8") ? 3 : 0;
  if (!channels) throw TruncatedData("Image encoding '" + e + "' is not a colour encoding");
  check_layout(img, static_cast<std::size_t>(channels));
  const cv::Mat m(static_cast<int>(img.height), static_cast<int>(img.width), CV_8UC(channels),
                  const_cast<std::uint8_t*>(img.data), img.step);
  width = static_cast<int>(img.width);
  height = static_cast<int>(img.height);
  const int code = e == "mono8"   ? cv::COLOR_GRAY2RGB
                   : e == "bgr8"  ? cv::COLOR_BGR2RGB
                   : e == "rgba8" ? cv::COLOR_RGBA2RGB
                   : e == "bgra8" ? cv::COLOR_BGRA2RGB
                                  : -1;
  return rgb_from_mat(m, code);
}

std::vector<std::uint8_t> decode_compressed_color(const RosCompressedImage& img, long long max_pixels, int& width,
                                                  int& height) {
  const cv::Mat bgr = decode_png_bytes(img.data, img.size, cv::IMREAD_COLOR, max_pixels);
  width = bgr.cols;
  height = bgr.rows;
  return rgb_from_mat(bgr, cv::COLOR_BGR2RGB);
}

}  // namespace tunnelmap::recordings
