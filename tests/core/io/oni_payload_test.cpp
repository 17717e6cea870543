// Frame payload checks of OpenNI recordings: a payload passes only when OpenNI's own decoder
// would stay inside it and produce exactly the stream's frame.
#include "core/io/oni_payload.h"

#include <gtest/gtest.h>

#include <vector>

namespace tunnelmap::oni {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::string problem(Codec codec, const Bytes& b, FrameShape shape) { return payload_problem(codec, b.data(), b.size(), shape); }

// A 16zT code for 2x2 pixels: a table {1000, 1500}, first index 0, then index 1 as a full
// value, index 1 again as a difference of 0 (high nibble 6, low nibble D = no second value),
// index 0 as a difference of -1 (high nibble 7).
Bytes table_code() { return {2, 0, 0xE8, 0x03, 0xDC, 0x05, 0, 0, 0xFF, 0x00, 0x01, 0x6D, 0x7D}; }

TEST(OniPayload, ATableCodeOfTheFramesSizePasses) {
  EXPECT_EQ(problem(Codec::Depth16zTable, table_code(), {2, 2, 2}), "");
}

TEST(OniPayload, ATableCodeGivingTooFewOrTooManyPixelsIsRefused) {
  EXPECT_EQ(problem(Codec::Depth16zTable, table_code(), {3, 2, 2}), "depth code gives 4 pixels, expected 6");
  EXPECT_EQ(problem(Codec::Depth16zTable, table_code(), {1, 2, 2}), "depth code gives more than the frame's 2 pixels");
}

TEST(OniPayload, AnIndexOutsideTheTableIsRefused) {
  Bytes b = table_code();
  b[10] = 0x07;  // the full value: index 7 of a table of 2
  EXPECT_EQ(problem(Codec::Depth16zTable, b, {2, 2, 2}), "depth code refers to value 7 of a table of 2");
}

TEST(OniPayload, ACodeEndingInsideAValueIsRefused) {
  Bytes b = table_code();
  b.resize(9);  // ends right after an escape byte: OpenNI would read on past the frame
  EXPECT_EQ(problem(Codec::Depth16zTable, b, {2, 2, 2}), "depth code ends inside a value");
}

TEST(OniPayload, ATableRunningPastTheFrameIsRefused) {
  EXPECT_EQ(problem(Codec::Depth16zTable, {0xFF, 0x7F, 1, 2, 3}, {2, 2, 2}),
            "depth value table of 32767 entries runs past the frame");
}

TEST(OniPayload, APlainCodeCountsRunsOfRepeatedValues) {
  // First value 1000, then 0xE1: two more of the same, then a difference of +0 twice (0x66).
  EXPECT_EQ(problem(Codec::Depth16z, {0xE8, 0x03, 0xE1, 0x66}, {5, 1, 2}), "");
  EXPECT_EQ(problem(Codec::Depth16z, {0xE8, 0x03, 0xE1, 0x66}, {2, 2, 2}), "depth code gives more than the frame's 4 pixels");
}

TEST(OniPayload, UncompressedFramesMustHaveTheFramesSize) {
  EXPECT_EQ(problem(Codec::Uncompressed, Bytes(12, 7), {2, 2, 3}), "");
  EXPECT_EQ(problem(Codec::Uncompressed, Bytes(11, 7), {2, 2, 3}), "11 bytes for a frame of 12");
}

// A JPEG outline: SOI, a frame header (SOF0) of w x h with 3 components, a scan header,
// two entropy-coded bytes and EOI. Only the layout is checked, not the image.
Bytes jpeg(std::uint16_t w, std::uint16_t h) {
  return {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 8, std::uint8_t(h >> 8), std::uint8_t(h), std::uint8_t(w >> 8), std::uint8_t(w), 3,
          1, 0x22, 0, 2, 0x11, 1, 3, 0x11, 1, 0xFF, 0xDA, 0x00, 0x0C, 3, 1, 0, 2, 0x11, 3, 0x11, 0, 0x3F, 0,
          0x12, 0xFF, 0x00, 0xFF, 0xD9};
}

TEST(OniPayload, AJpegFrameOfTheStreamsSizePasses) { EXPECT_EQ(problem(Codec::Jpeg, jpeg(640, 480), {640, 480, 3}), ""); }

TEST(OniPayload, AJpegFrameOfAnotherSizeIsRefused) {
  EXPECT_EQ(problem(Codec::Jpeg, jpeg(640, 481), {640, 480, 3}), "JPEG frame is 640x481 with 3 components, the stream 640x480 RGB");
}

TEST(OniPayload, AJpegSegmentRunningPastTheFrameIsRefused) {
  Bytes b = jpeg(640, 480);
  b[4] = 0x40;  // the frame header's length: 16 KB
  EXPECT_EQ(problem(Codec::Jpeg, b, {640, 480, 3}), "JPEG segment at byte 2 runs past the frame");
}

TEST(OniPayload, AMarkerInsideTheScanOrAMissingEndIsRefused) {
  Bytes b = jpeg(640, 480);
  b[b.size() - 3] = 0xC4;  // FF 00 -> FF C4: a table marker inside the entropy-coded bytes
  EXPECT_EQ(problem(Codec::Jpeg, b, {640, 480, 3}), "JPEG scan holds a marker at byte 36");
  b = jpeg(640, 480);
  b.back() = 0x00;
  EXPECT_EQ(problem(Codec::Jpeg, b, {640, 480, 3}), "JPEG frame does not end with its end-of-image marker");
}

}  // namespace
}  // namespace tunnelmap::oni
