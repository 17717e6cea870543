// The structural check of OpenNI recordings, on recordings built here record by record in the
// layout OpenNI2's recorder writes (a depth stream in the 16zT code and an uncompressed colour
// stream), then damaged one field at a time.
#include "core/io/oni_container.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/io/input_options.h"
#include "core/util/error.h"

namespace tunnelmap::oni {
namespace {

class Recording {
 public:
  Recording() {
    bytes_ = "NI10";
    // Version 1.0.1.0 (major and minor bytes, then maintenance and build), no last timestamp, nodes up to 2.
    put16(1), put16(1), put32(0), put64(~0ull), put32(2);
  }
  // Appends one record; returns its position.
  std::size_t record(std::uint32_t type, std::uint32_t node, const std::string& fields = {}, const std::string& payload = {}) {
    const std::size_t at = bytes_.size();
    put32(0x0052494E), put32(type), put32(node), put32(static_cast<std::uint32_t>(28 + fields.size()));
    put32(static_cast<std::uint32_t>(payload.size())), put64(0);
    bytes_ += fields + payload;
    return at;
  }
  static std::string text(const std::string& s) { return u32(static_cast<std::uint32_t>(s.size() + 1)) + s + '\0'; }
  static std::string u32(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }
  static std::string u64(std::uint64_t v) { return std::string(reinterpret_cast<const char*>(&v), 8); }
  void property(std::uint32_t type, std::uint32_t node, const std::string& name, const std::string& data) {
    record(type, node, text(name) + u32(static_cast<std::uint32_t>(data.size())) + data);
  }
  void stream(std::uint32_t node, const std::string& name, std::uint32_t type, const char* codec, std::uint32_t pixel_format) {
    record(13, node, text(name) + u32(type) + std::string(codec, 4) + u32(1) + u64(0) + u64(0) + u64(0));
    property(6, node, "xnMapOutputMode", u32(2) + u32(2) + u32(30));
    property(3, node, "oniPixelFormat", u64(pixel_format));
    record(9, node);  // ready
    record(8, node, u32(1) + u64(0));  // data begins
  }
  std::string& bytes() { return bytes_; }

 private:
  void put16(std::uint16_t v) { bytes_.append(reinterpret_cast<const char*>(&v), 2); }
  void put32(std::uint32_t v) { bytes_.append(reinterpret_cast<const char*>(&v), 4); }
  void put64(std::uint64_t v) { bytes_.append(reinterpret_cast<const char*>(&v), 8); }
  std::string bytes_;
};

// 2x2 depth in the 16zT code: table {1000, 1500}; indices 0, 1 (full value), 1, 0.
const std::string kDepthCode("\x02\x00\xE8\x03\xDC\x05\x00\x00\xFF\x00\x01\x6D\x7D", 13);

struct Built {
  std::string bytes;
  std::size_t depth_frame = 0;  // position of the depth frame record
};

Built one_frame_recording() {
  Recording r;
  r.stream(1, "Depth", 2, "16zT", 100);
  r.stream(2, "Image", 3, "NONE", 200);
  r.record(10, 2, Recording::u64(0) + Recording::u32(1), std::string(12, '\x40'));
  const std::size_t depth = r.record(10, 1, Recording::u64(0) + Recording::u32(1), kDepthCode);
  r.record(11, 0);
  return {r.bytes(), depth};
}

std::string problem(const std::string& bytes) {
  try {
    check_recording(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), "rec.oni",
                    input_keys::max_image_pixels.default_value);
    return "";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "rec.oni");
    return e.problem();
  }
}

void set_u32(std::string& b, std::size_t at, std::uint32_t v) { std::memcpy(&b[at], &v, 4); }

TEST(OniContainer, ARecordingInTheRecordersLayoutPasses) { EXPECT_EQ(problem(one_frame_recording().bytes), ""); }

TEST(OniContainer, AnotherFileOrVersionIsRefused) {
  EXPECT_EQ(problem("not a recording at all, just text"), "damaged OpenNI recording: no NI10 file marker (not an .oni recording)");
  std::string b = one_frame_recording().bytes;
  b[4] = 2;
  EXPECT_EQ(problem(b), "damaged OpenNI recording: format version 2.0.1.0 is not supported (OpenNI 2 writes 1.0.1.0)");
}

TEST(OniContainer, ARecordRunningPastTheFileIsRefused) {
  Built r = one_frame_recording();
  set_u32(r.bytes, r.depth_frame + 16, 1u << 20);  // payload size 1 MB
  EXPECT_EQ(problem(r.bytes), "damaged OpenNI recording: record of 1048616 bytes runs past the end of the file (truncated?) (record at byte " +
                                  std::to_string(r.depth_frame) + ")");
}

TEST(OniContainer, ATruncatedRecordingIsRefused) {
  const std::string b = one_frame_recording().bytes;
  EXPECT_EQ(problem(b.substr(0, b.size() - 28)), "damaged OpenNI recording: ends after byte " + std::to_string(b.size() - 28) +
                                                     " without its end record (truncated?)");
}

TEST(OniContainer, AnUnknownPropertyNameIsRefused) {
  std::string b = one_frame_recording().bytes;
  const std::size_t at = b.find("oniPixelFormat");
  b[at] = 'O';
  EXPECT_NE(problem(b).find("unknown property 'OniPixelFormat'"), std::string::npos) << problem(b);
}

TEST(OniContainer, AFrameOutOfOrderOrOfAnotherNodeIsRefused) {
  Built r = one_frame_recording();
  set_u32(r.bytes, r.depth_frame + 36, 2);  // frame number 2 of 1
  EXPECT_NE(problem(r.bytes).find("frame 2 of stream 'Depth' out of order (after frame 0 of 1)"), std::string::npos) << problem(r.bytes);
  r = one_frame_recording();
  set_u32(r.bytes, r.depth_frame + 8, 7);  // node 7, above the header's 2
  EXPECT_NE(problem(r.bytes).find("node id 7 above the header's 2"), std::string::npos) << problem(r.bytes);
}

TEST(OniContainer, ADamagedFramePayloadIsRefusedWithItsStream) {
  Built r = one_frame_recording();
  r.bytes[r.depth_frame + 40 + 10] = 0x09;  // the full value: index 9 of a table of 2
  EXPECT_EQ(problem(r.bytes), "damaged OpenNI recording: frame 1 of stream 'Depth': depth code refers to value 9 of a table of 2 (record at byte " +
                                  std::to_string(r.depth_frame) + ")");
}

TEST(OniContainer, AFrameSizeDisagreeingWithTheResolutionIsRefused) {
  std::string b = one_frame_recording().bytes;
  const std::size_t mode = b.find("xnMapOutputMode") + 16 + 4;  // name, NUL, data size
  set_u32(b, mode, 3);  // 3x2 depth pixels, but the code gives 4
  EXPECT_NE(problem(b).find("depth code gives 4 pixels, expected 6"), std::string::npos) << problem(b);
}

}  // namespace
}  // namespace tunnelmap::oni
