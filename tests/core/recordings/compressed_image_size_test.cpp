// Compressed images from bags are sized from their headers and refused over the pixel limit
// before they are decoded.
#include "core/recordings/compressed_image_size.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/depth_image_decode.h"

namespace tunnelmap::recordings {
namespace {

std::vector<std::uint8_t> encoded(const std::string& ext, int width, int height, int type) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(ext, cv::Mat::zeros(height, width, type), bytes));
  return bytes;
}

TEST(CompressedImageSize, PngAndJpegHeadersGiveTheirSize) {
  int w = 0, h = 0;
  const std::vector<std::uint8_t> png = encoded(".png", 100, 50, CV_16UC1);
  ASSERT_TRUE(compressed_image_size(png.data(), png.size(), w, h));
  EXPECT_EQ(w, 100);
  EXPECT_EQ(h, 50);
  const std::vector<std::uint8_t> jpeg = encoded(".jpg", 64, 48, CV_8UC3);
  ASSERT_TRUE(compressed_image_size(jpeg.data(), jpeg.size(), w, h));
  EXPECT_EQ(w, 64);
  EXPECT_EQ(h, 48);
}

TEST(CompressedImageSize, OtherBytesAndCutHeadersHaveNoSize) {
  int w = 0, h = 0;
  const std::vector<std::uint8_t> garbage(64, 0x42);
  EXPECT_FALSE(compressed_image_size(garbage.data(), garbage.size(), w, h));
  const std::vector<std::uint8_t> png = encoded(".png", 10, 10, CV_8UC1);
  EXPECT_FALSE(compressed_image_size(png.data(), 20, w, h));
  const std::vector<std::uint8_t> jpeg = encoded(".jpg", 10, 10, CV_8UC3);
  EXPECT_FALSE(compressed_image_size(jpeg.data(), 6, w, h));
  EXPECT_FALSE(compressed_image_size(nullptr, 0, w, h));
}

TEST(CompressedImageSize, AColourImageOverTheLimitIsRefusedBeforeDecoding) {
  const std::vector<std::uint8_t> png = encoded(".png", 100, 50, CV_8UC3);
  RosCompressedImage img;
  img.format = "png";
  img.data = png.data();
  img.size = png.size();
  int w = 0, h = 0;
  EXPECT_EQ(decode_compressed_color(img, 5000, w, h).size(), 100u * 50u * 3u);
  try {
    decode_compressed_color(img, 4999, w, h);
    FAIL() << "an image over the limit was decoded";
  } catch (const TruncatedData& e) {
    EXPECT_NE(std::string(e.what()).find("100x50 pixels is over input.max_image_pixels = 4999"), std::string::npos)
        << e.what();
  }
}

TEST(CompressedImageSize, ACompressedDepthOverTheLimitIsRefusedBeforeDecoding) {
  std::vector<std::uint8_t> bytes(12, 0);  // format and the two inverse-depth parameters
  const std::vector<std::uint8_t> png = encoded(".png", 80, 60, CV_16UC1);
  bytes.insert(bytes.end(), png.begin(), png.end());
  RosCompressedImage img;
  img.format = "16UC1; compressedDepth png";
  img.data = bytes.data();
  img.size = bytes.size();
  EXPECT_EQ(decode_compressed_depth(img, 4800).width, 80);
  EXPECT_THROW(decode_compressed_depth(img, 4799), TruncatedData);
  std::vector<std::uint8_t> not_an_image(40, 0x11);
  img.data = not_an_image.data();
  img.size = not_an_image.size();
  EXPECT_THROW(decode_compressed_depth(img, 4800), TruncatedData);
}

}  // namespace
}  // namespace tunnelmap::recordings
