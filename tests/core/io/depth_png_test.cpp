// The depth PNG reader (and the RGB image reader beside it): round trips, hostile files, real
// frames from resources/real-frames.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/io/depth_png.h"
#include "core/io/read_options.h"
#include "core/util/build_paths.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;
using testing::expect_input_error;

constexpr long long kDefaultMaxPixels = input_keys::max_image_pixels.default_value;

cv::Mat depth_ramp(int w, int h) {
  cv::Mat img(h, w, CV_16UC1);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) img.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(500 + 37 * v + u);
  img.at<std::uint16_t>(0, 0) = 0;       // no measurement
  img.at<std::uint16_t>(1, 1) = 65535;   // largest value survives
  return img;
}

TEST(DepthPng, RoundTripKeepsValuesAndScalesDefaultIntrinsics) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  const cv::Mat img = depth_ramp(320, 240);
  ASSERT_TRUE(cv::imwrite(path, img));

  const DepthFrame f = read_depth_png(path, ReadOptions{});
  ASSERT_EQ(f.width, 320);
  ASSERT_EQ(f.height, 240);
  EXPECT_EQ(f.source, path);
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 1000.0);
  EXPECT_FALSE(f.has_rgb());
  EXPECT_FALSE(f.pose.has_value());
  for (int v = 0; v < 240; v += 7)
    for (int u = 0; u < 320; u += 5)
      ASSERT_EQ(f.depth[v * 320 + u], static_cast<float>(img.at<std::uint16_t>(v, u)));
  EXPECT_EQ(f.depth[0], 0.f);
  EXPECT_EQ(f.depth[321], 65535.f);
  EXPECT_FLOAT_EQ(f.depth_m(10, 2), (500 + 37 * 2 + 10) / 1000.f);
  // PrimeSense VGA scaled to half size.
  EXPECT_NEAR(f.intrinsics.fx, 285.15, 1e-9);
  EXPECT_NEAR(f.intrinsics.fy, 285.15, 1e-9);
  EXPECT_NEAR(f.intrinsics.cx, 159.5, 1e-9);
  EXPECT_NEAR(f.intrinsics.cy, 119.5, 1e-9);
  EXPECT_EQ(f.intrinsics.width, 320);
  EXPECT_EQ(f.intrinsics.height, 240);
}

TEST(DepthPng, UsesGivenScaleAndIntrinsicsWithImageSize) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  ASSERT_TRUE(cv::imwrite(path, depth_ramp(64, 48)));
  ReadOptions opt;
  opt.depth_units_per_m = 5000;
  opt.intrinsics = Intrinsics{525, 526, 31, 23, 640, 480};
  const DepthFrame f = read_depth_png(path, opt);
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 5000);
  EXPECT_DOUBLE_EQ(f.intrinsics.fx, 525);
  EXPECT_DOUBLE_EQ(f.intrinsics.fy, 526);
  EXPECT_DOUBLE_EQ(f.intrinsics.cx, 31);
  EXPECT_EQ(f.intrinsics.width, 64);   // from the image, not the option
  EXPECT_EQ(f.intrinsics.height, 48);
  EXPECT_FLOAT_EQ(f.depth_m(3, 2), (500 + 74 + 3) / 5000.f);
}

TEST(DepthPng, Rejects8BitAndColourImages) {
  IoTempDir tmp;
  const std::string grey8 = tmp.file("grey8.png"), bgr8 = tmp.file("bgr8.png"),
                    bgr16 = tmp.file("bgr16.png");
  ASSERT_TRUE(cv::imwrite(grey8, cv::Mat(20, 30, CV_8UC1, cv::Scalar(100))));
  ASSERT_TRUE(cv::imwrite(bgr8, cv::Mat(20, 30, CV_8UC3, cv::Scalar(1, 2, 3))));
  ASSERT_TRUE(cv::imwrite(bgr16, cv::Mat(20, 30, CV_16UC3, cv::Scalar(1000, 2000, 3000))));
  expect_input_error([&] { read_depth_png(grey8, {}); }, {grey8, "is an 8-bit grey image; depth PNGs must be 16-bit single channel"});
  expect_input_error([&] { read_depth_png(bgr8, {}); }, {bgr8, "8-bit", "16-bit single channel"});
  expect_input_error([&] { read_depth_png(bgr16, {}); }, {bgr16, "RGB", "16-bit single channel"});
}

TEST(DepthPng, RejectsTruncatedFile) {
  IoTempDir tmp;
  const std::string good = tmp.file("good.png");
  cv::Mat img(240, 320, CV_16UC1);
  cv::randu(img, 0, 8000);  // incompressible, so cutting loses image rows
  ASSERT_TRUE(cv::imwrite(good, img));
  const auto bytes = testing::read_binary_file(good);
  ASSERT_GT(bytes.size(), 1000u);

  const std::string half = tmp.file("half.png");
  testing::write_binary_file(half, std::vector<char>(bytes.begin(), bytes.begin() + bytes.size() / 2));
  expect_input_error([&] { read_depth_png(half, {}); }, {half, "truncated"});

  // Only the IEND chunk missing: the pixels are all there but the file is still cut short.
  const std::string no_end = tmp.file("no_end.png");
  testing::write_binary_file(no_end, std::vector<char>(bytes.begin(), bytes.end() - 12));
  expect_input_error([&] { read_depth_png(no_end, {}); }, {no_end, "truncated"});

  // Header only.
  const std::string header_only = tmp.file("header_only.png");
  testing::write_binary_file(header_only, std::vector<char>(bytes.begin(), bytes.begin() + 40));
  expect_input_error([&] { read_depth_png(header_only, {}); }, {header_only});
}

TEST(DepthPng, RejectsTextFileRenamedPng) {
  IoTempDir tmp;
  const std::string path = tmp.file("notes.png");
  testing::write_text_file(path, "this is not an image, just some text\nsecond line\n");
  expect_input_error([&] { read_depth_png(path, {}); }, {path, "is not a PNG"});
  const std::string empty = tmp.file("empty.png");
  testing::write_text_file(empty, "");
  expect_input_error([&] { read_depth_png(empty, {}); }, {empty, "is not a PNG"});
}

// A PNG signature and IHDR claiming the given size, and nothing else.
std::vector<char> png_header_bytes(std::uint32_t w, std::uint32_t h) {
  std::vector<char> b = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  for (std::uint32_t x : {w, h})
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<char>((x >> s) & 0xff));
  for (char c : {16, 0, 0, 0, 0}) b.push_back(c);  // 16-bit grey
  for (int i = 0; i < 4; ++i) b.push_back(0);       // CRC (not checked before the size test)
  return b;
}

TEST(DepthPng, RejectsAbsurdHeaderDimensionsBeforeDecoding) {
  IoTempDir tmp;
  const std::string huge = tmp.file("huge.png"), wide = tmp.file("wide.png"), zero = tmp.file("zero.png");
  testing::write_binary_file(huge, png_header_bytes(2000000000u, 2000000000u));
  testing::write_binary_file(wide, png_header_bytes(8193, 10));
  testing::write_binary_file(zero, png_header_bytes(0, 480));
  // "absurd image size" comes from the header check: the decoder never ran.
  expect_input_error([&] { read_depth_png(huge, {}); }, {huge, "absurd image size 2000000000x2000000000"});
  expect_input_error([&] { read_depth_png(wide, {}); }, {wide, "absurd image size 8193x10"});
  expect_input_error([&] { read_depth_png(zero, {}); }, {zero, "absurd image size 0x480"});
}

TEST(DepthPng, MissingFileAndFolder) {
  IoTempDir tmp;
  const std::string missing = tmp.file("nope.png");
  expect_input_error([&] { read_depth_png(missing, {}); }, {missing, "not found"});
  expect_input_error([&] { read_depth_png(tmp.path().string(), {}); }, {"is a folder"});
}

TEST(DepthPng, AllZeroDepthReadsAsFrameWithNoValidPixel) {
  // Decision (docs/robustness.md): a blank frame is data, not an error; the pipeline reports
  // "no tunnel" for it, so one blinded frame does not abort a whole sequence.
  IoTempDir tmp;
  const std::string path = tmp.file("zero.png");
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(24, 32, CV_16UC1, cv::Scalar(0))));
  const DepthFrame f = read_depth_png(path, {});
  ASSERT_EQ(f.depth.size(), 32u * 24u);
  for (float d : f.depth) EXPECT_EQ(d, 0.f);
}

TEST(RgbImage, AcceptsPngAndJpegOnly) {
  IoTempDir tmp;
  const cv::Mat bgr(6, 8, CV_8UC3, cv::Scalar(30, 20, 200));
  for (const char* name : {"c.png", "c.jpg", "c.bmp"}) ASSERT_TRUE(cv::imwrite(tmp.file(name), bgr));
  int w = 0, h = 0;
  for (const char* name : {"c.png", "c.jpg"}) {
    const auto rgb = read_rgb_image(tmp.file(name), w, h, kDefaultMaxPixels);
    ASSERT_EQ(rgb.size(), 8u * 6u * 3u);
    EXPECT_NEAR(rgb[0], 200, 3) << name;  // red first
    EXPECT_NEAR(rgb[2], 30, 3) << name;
  }
  // OpenCV would decode BMP, TIFF, EXR...: only the formats datasets use are let through.
  expect_input_error([&] { read_rgb_image(tmp.file("c.bmp"), w, h, kDefaultMaxPixels); }, {"c.bmp", "neither a PNG nor a JPEG"});
  // A JPEG whose frame header claims 60000x50000 is refused before decoding.
  auto jpeg = testing::read_binary_file(tmp.file("c.jpg"));
  for (std::size_t i = 2; i + 9 < jpeg.size(); ++i)
    if (std::uint8_t(jpeg[i]) == 0xff && std::uint8_t(jpeg[i + 1]) == 0xc0) {
      jpeg[i + 5] = char(50000 >> 8), jpeg[i + 6] = char(50000 & 0xff);
      jpeg[i + 7] = char(60000 >> 8), jpeg[i + 8] = char(60000 & 0xff);
      break;
    }
  testing::write_binary_file(tmp.file("huge.jpg"), jpeg);
  expect_input_error([&] { read_rgb_image(tmp.file("huge.jpg"), w, h, kDefaultMaxPixels); }, {"huge.jpg", "absurd image size 60000x50000"});
}

// libjpeg called directly decodes what OpenCV's decoder (the same libjpeg) gave, pixel for pixel.
TEST(RgbImage, JpegDecodesAsOpenCvDecodesIt) {
  IoTempDir tmp;
  cv::Mat bgr(48, 64, CV_8UC3);
  cv::randu(bgr, cv::Scalar::all(0), cv::Scalar::all(255));
  ASSERT_TRUE(cv::imwrite(tmp.file("r.jpg"), bgr));
  const cv::Mat expected = cv::imread(tmp.file("r.jpg"), cv::IMREAD_COLOR);
  int w = 0, h = 0;
  const auto rgb = read_rgb_image(tmp.file("r.jpg"), w, h, kDefaultMaxPixels);
  ASSERT_EQ(w, 64);
  ASSERT_EQ(h, 48);
  int differing = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
      for (int c = 0; c < 3; ++c)
        differing += rgb[(static_cast<std::size_t>(v) * w + u) * 3 + c] != expected.at<cv::Vec3b>(v, u)[2 - c];
  EXPECT_EQ(differing, 0);
}

TEST(RgbImage, AGreyJpegAndOneOverThePixelLimitAreRefused) {
  IoTempDir tmp;
  ASSERT_TRUE(cv::imwrite(tmp.file("g.jpg"), cv::Mat(6, 8, CV_8UC1, cv::Scalar(90))));
  ASSERT_TRUE(cv::imwrite(tmp.file("c.jpg"), cv::Mat(6, 8, CV_8UC3, cv::Scalar(1, 2, 3))));
  int w = 0, h = 0;
  expect_input_error([&] { read_rgb_image(tmp.file("g.jpg"), w, h, kDefaultMaxPixels); },
                     {"g.jpg", "RGB images must be 8-bit 3-channel colour (a 1-component JPEG)"});
  expect_input_error([&] { read_rgb_image(tmp.file("c.jpg"), w, h, 47); },
                     {"c.jpg", "image of 8x6 pixels is too large (at most 47 = 0.0 Mpx, input.max_image_pixels)"});
  EXPECT_EQ(read_rgb_image(tmp.file("c.jpg"), w, h, 48).size(), 8u * 6u * 3u);
}

TEST(DepthPng, DecodesFromMemoryLikeFromFile) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  ASSERT_TRUE(cv::imwrite(path, depth_ramp(20, 10)));
  const auto raw = testing::read_binary_file(path);
  const std::vector<std::uint8_t> bytes(raw.begin(), raw.end());
  const DepthFrame a = read_depth_png(path, {}), b = decode_depth_png(bytes, "mem.png", {});
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(b.source, "mem.png");
  // Every truncation of a valid PNG is refused (or, if the cut is after IEND, read intact).
  for (std::size_t n = 0; n + 12 < bytes.size(); ++n)
    expect_input_error([&] { decode_depth_png({bytes.begin(), bytes.begin() + n}, "cut.png", {}); }, {"cut.png"});
}

struct RealFrame {
  const char* file;
  Intrinsics k;  // from resources/real-frames/SOURCES.md
  double min_valid_fraction;
  float min_mm, max_mm;
};

TEST(RealFrames, ReadWithSaneValidFractionAndDepthRange) {
  const RealFrame frames[] = {
      {"cape_tunnel_depth.png", {575.927, 576.408, 315.150, 230.586, 640, 480}, 0.7, 500, 8000},
      {"pcl_office_depth.png", {525, 525, 320, 240, 640, 480}, 0.7, 500, 8000},
      {"rtabmap_lab_depth_17.png", {525, 525, 319.5, 239.5, 640, 480}, 0.7, 500, 8000},
  };
  for (const RealFrame& rf : frames) {
    const std::string path = std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/" + rf.file;
    ReadOptions opt;
    opt.intrinsics = rf.k;
    const DepthFrame f = read_depth_png(path, opt);
    ASSERT_EQ(f.width, 640);
    ASSERT_EQ(f.height, 480);
    EXPECT_DOUBLE_EQ(f.intrinsics.fx, rf.k.fx);
    EXPECT_DOUBLE_EQ(f.intrinsics.cy, rf.k.cy);
    std::size_t valid = 0;
    float lo = std::numeric_limits<float>::max(), hi = 0;
    for (float d : f.depth)
      if (d > 0) {
        ++valid;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    const double fraction = double(valid) / f.depth.size();
    std::printf("%s: valid %.3f, depth %.3f .. %.3f m\n", rf.file, fraction, lo / 1000.0, hi / 1000.0);
    EXPECT_GT(fraction, rf.min_valid_fraction) << rf.file;
    EXPECT_GE(lo, rf.min_mm) << rf.file;
    EXPECT_LE(hi, rf.max_mm) << rf.file;
  }
}

}  // namespace
}  // namespace tunnelmap
