// The simulated posed sequence written as ROS 1 bags by the real writer (rosbag_storage):
// 16UC1 or compressedDepth depth, camera info, colour, the camera pose as /tf odom <- base_link
// over a /tf_static base_link <- camera. Each reads back as the dataset's frames, and `detect`
// gives the dataset's results.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "tests/core/recordings/round_trip_support.h"
#include "tests/support/posed_bag.h"
#include "tests/support/ros1_message_writer.h"
#include "tests/support_ros1/ros1_bag_writer.h"

namespace tunnelmap {
namespace {

using testing::SimulatedSequence;
namespace ros1 = testing::ros1;

// The camera's mounting on the robot base (base_link <- camera_depth_optical_frame).
Eigen::Isometry3d camera_mount() {
  Eigen::Isometry3d S = Eigen::Isometry3d::Identity();
  S.linear() = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  S.translation() = Eigen::Vector3d(0.12, -0.03, 0.25);
  return S;
}

// image_transport's compressedDepth: format, two inverse-depth parameters (unused for 16UC1), PNG.
std::vector<std::uint8_t> compressed_depth_png(const DepthFrame& f) {
  cv::Mat mm(f.height, f.width, CV_16UC1);
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) mm.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(f.depth[v * f.width + u]);
  std::vector<std::uint8_t> png;
  cv::imencode(".png", mm, png);
  std::vector<std::uint8_t> data(12, 0);
  data.insert(data.end(), png.begin(), png.end());
  return data;
}

std::string write_ros1_bag(const SimulatedSequence& seq, const std::string& compression, bool compressed_depth) {
  const std::string path = seq.tmp.file("posed_" + compression + (compressed_depth ? "_cd" : "") + ".bag");
  testing::Ros1BagWriter bag(path, compression);
  const Eigen::Isometry3d mount = camera_mount();
  const std::string cam = testing::kBagCameraFrame;
  bag.write("/tf_static", "tf2_msgs/TFMessage", ros1::kTfMessageMd5, testing::bag_stamp_ns(seq.ds, 0),
            ros1::tf_message(testing::bag_stamp_ns(seq.ds, 0), "base_link", cam, mount));
  for (std::size_t i = 0; i < seq.ds.frames.size(); ++i) {
    const DepthFrame f = seq.ds.load_frame(i);
    const std::int64_t t = testing::bag_stamp_ns(seq.ds, i);
    const auto w = static_cast<std::uint32_t>(f.width), h = static_cast<std::uint32_t>(f.height);
    bag.write("/tf", "tf2_msgs/TFMessage", ros1::kTfMessageMd5, t,
              ros1::tf_message(t, "odom", "base_link", *f.pose * mount.inverse()));
    bag.write("/camera/depth/camera_info", "sensor_msgs/CameraInfo", ros1::kCameraInfoMd5, t,
              ros1::camera_info(t, cam, w, h, f.intrinsics.fx, f.intrinsics.fy, f.intrinsics.cx, f.intrinsics.cy));
    if (compressed_depth) {
      bag.write("/camera/depth/image_raw/compressedDepth", "sensor_msgs/CompressedImage", ros1::kCompressedImageMd5, t,
                ros1::compressed_image(t, cam, "16UC1; compressedDepth png", compressed_depth_png(f)));
    } else {
      std::vector<std::uint8_t> mm(f.depth.size() * 2);
      for (std::size_t k = 0; k < f.depth.size(); ++k) {
        const auto d = static_cast<std::uint16_t>(f.depth[k]);
        std::memcpy(&mm[k * 2], &d, 2);
      }
      bag.write("/camera/depth/image_raw", "sensor_msgs/Image", ros1::kImageMd5, t,
                ros1::image(t, cam, w, h, "16UC1", w * 2, mm));
    }
    bag.write("/camera/color/image_raw", "sensor_msgs/Image", ros1::kImageMd5, t,
              ros1::image(t, "camera_color_optical_frame", w, h, "rgb8", w * 3, f.rgb));
  }
  return path;
}

TEST(Ros1RoundTrip, Lz4Bag16UC1ReadsBackAndDetectsAsTheDataset) {
  const SimulatedSequence seq;
  const std::string bag = write_ros1_bag(seq, "lz4", false);
  testing::expect_same_frames(seq.ds, bag);
  testing::expect_same_detections(testing::detect_json(seq.tmp, seq.dataset_dir, "original"),
                                  testing::detect_json(seq.tmp, bag, "bag"));
}

TEST(Ros1RoundTrip, CompressedDepthAndBz2ReadBack) {
  const SimulatedSequence seq;
  testing::expect_same_frames(seq.ds, write_ros1_bag(seq, "bz2", true));
  testing::expect_same_frames(seq.ds, write_ros1_bag(seq, "none", false));
}

}  // namespace
}  // namespace tunnelmap
