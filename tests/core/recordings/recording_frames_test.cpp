// Depth frames from a recording: a known lens distortion is removed, an inconsistent image
// is refused with its topic and time, and a missing camera info names the depth topic.
#include <gtest/gtest.h>

#include <cstring>
#include <opencv2/calib3d.hpp>

#include "core/io/frame_source.h"
#include "core/util/error.h"
#include "tests/support/cdr_writer.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/mcap_writer.h"

namespace tunnelmap {
namespace {

using testing::cdr_camera_info;
using testing::cdr_image;

constexpr int kW = 320, kH = 240;
constexpr double kFx = 260, kFy = 260, kCx = 160, kCy = 120;
constexpr std::int64_t kStamp = 1700000000LL * 1000000000LL;
const std::vector<double> kDistortion = {-0.25, 0.06, 0.001, -0.002, 0.0};

// A tilted wall z = a + b x seen along the normalised ray (xn, yn, 1): z = a / (1 - b xn).
double wall_depth_m(double xn) { return 2.0 / (1.0 - 0.5 * xn); }

// What a camera with kDistortion records: each distorted pixel sees the wall along its
// undistorted ray.
std::vector<std::uint16_t> distorted_wall_mm() {
  std::vector<cv::Point2f> pixels;
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) pixels.emplace_back(static_cast<float>(u), static_cast<float>(v));
  const cv::Matx33d K(kFx, 0, kCx, 0, kFy, kCy, 0, 0, 1);
  std::vector<cv::Point2f> rays;
  cv::undistortPoints(pixels, rays, K, kDistortion);
  std::vector<std::uint16_t> mm(pixels.size());
  for (std::size_t k = 0; k < rays.size(); ++k)
    mm[k] = static_cast<std::uint16_t>(std::lround(wall_depth_m(rays[k].x) * 1000.0));
  return mm;
}

std::string write_depth_bag(const testing::IoTempDir& tmp, const std::vector<std::uint16_t>& mm,
                            std::uint32_t step, std::size_t data_bytes, bool with_info) {
  const std::string path = tmp.file("depth.mcap");
  testing::McapWriter w(path, {});
  std::vector<std::uint8_t> data(data_bytes);
  std::memcpy(data.data(), mm.data(), std::min(data_bytes, mm.size() * 2));
  if (with_info)
    w.write("/cam/depth/camera_info", "sensor_msgs/msg/CameraInfo", kStamp,
            cdr_camera_info(kStamp, "cam", kW, kH, kFx, kFy, kCx, kCy, kDistortion));
  w.write("/cam/depth/image_raw", "sensor_msgs/msg/Image", kStamp,
          cdr_image(kStamp, "cam", kW, kH, "16UC1", step, data));
  w.close();
  return path;
}

// Mean |depth - the pinhole model's depth| over measured pixels, in metres.
double mean_error_m(const DepthFrame& f) {
  double sum = 0;
  std::size_t n = 0;
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const float z = f.depth_m(u, v);
      if (!(z > 0)) continue;
      sum += std::abs(z - wall_depth_m((u - kCx) / kFx));
      ++n;
    }
  return n ? sum / n : 1e9;
}

TEST(RecordingFrames, KnownDistortionIsRemoved) {
  testing::IoTempDir tmp;
  const std::vector<std::uint16_t> mm = distorted_wall_mm();
  const std::string bag = write_depth_bag(tmp, mm, kW * 2, mm.size() * 2, true);
  const auto source = open_input(bag, ReadOptions{});
  ASSERT_EQ(source->size(), 1u);
  const DepthFrame f = source->load(0);
  EXPECT_EQ(f.intrinsics.fx, kFx);
  EXPECT_EQ(f.intrinsics.cx, kCx);
  // The recorded (distorted) image against the pinhole model: centimetres off at the edges.
  DepthFrame raw = f;
  for (std::size_t k = 0; k < mm.size(); ++k) raw.depth[k] = mm[k];
  EXPECT_GT(mean_error_m(raw), 0.01);
  // Undistorted: within the millimetre quantisation and half a pixel of nearest neighbour.
  EXPECT_LT(mean_error_m(f), 0.0015);
}

TEST(RecordingFrames, InconsistentImageIsRefusedWithTopicAndTime) {
  testing::IoTempDir tmp;
  const std::vector<std::uint16_t> mm(kW * kH, 1500);
  const std::string bag = write_depth_bag(tmp, mm, kW * 2, 30, true);  // 30 bytes for 320x240
  try {
    open_input(bag, ReadOptions{});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/cam/depth/image_raw"), std::string::npos) << what;
    EXPECT_NE(what.find("t=1700000000.000000 s"), std::string::npos) << what;
    EXPECT_NE(what.find("holds 30 data bytes"), std::string::npos) << what;
  }
}

TEST(RecordingFrames, MissingCameraInfoNamesTheDepthTopic) {
  testing::IoTempDir tmp;
  const std::vector<std::uint16_t> mm(kW * kH, 1500);
  const std::string bag = write_depth_bag(tmp, mm, kW * 2, mm.size() * 2, false);
  try {
    open_input(bag, ReadOptions{});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("depth topic /cam/depth/image_raw has no camera info"), std::string::npos)
        << e.what();
  }
  ReadOptions with_intrinsics;
  with_intrinsics.intrinsics = Intrinsics{300, 300, 160, 120, 0, 0};
  const DepthFrame f = open_input(bag, with_intrinsics)->load(0);
  EXPECT_EQ(f.intrinsics.fx, 300);
  EXPECT_EQ(f.intrinsics.width, kW);
  EXPECT_FLOAT_EQ(f.depth_m(10, 10), 1.5f);
}

}  // namespace
}  // namespace tunnelmap
