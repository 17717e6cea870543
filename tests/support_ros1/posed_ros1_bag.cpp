#include "tests/support_ros1/posed_ros1_bag.h"

#include <cstring>
#include <opencv2/imgcodecs.hpp>

#include "tests/support/imu_at_rest.h"
#include "tests/support/posed_bag.h"
#include "tests/support/ros1_message_writer.h"
#include "tests/support_ros1/ros1_bag_writer.h"

namespace tunnelmap::testing {
namespace {

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

// The base IMU's readings around the frame (before or from its stamp): the camera's gravity
// turned into the base through the mounting.
void write_base_imu(Ros1BagWriter& bag, const DepthFrame& f, std::int64_t t, bool before) {
  if (!f.gravity) return;
  const Eigen::Vector3d falling_in_base = camera_mount().linear() * *f.gravity;
  for (const ImuReading& r : imu_at_rest(t, falling_in_base))
    if ((r.stamp_ns < t) == before)
      bag.write("/imu/data", "sensor_msgs/Imu", ros1::kImuMd5, r.stamp_ns, ros1::imu(r.stamp_ns, "base_link", r.specific_force));
}

}  // namespace

void write_posed_ros1_bag(const Dataset& ds, const std::string& path, const Ros1PosedBagOptions& o) {
  Ros1BagWriter bag(path, o.compression);
  const Eigen::Isometry3d mount = camera_mount();
  const std::string cam = kBagCameraFrame;
  bag.write("/tf_static", "tf2_msgs/TFMessage", ros1::kTfMessageMd5, bag_stamp_ns(ds, 0),
            ros1::tf_message(bag_stamp_ns(ds, 0), "base_link", cam, mount));
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    const DepthFrame f = ds.load_frame(i);
    const std::int64_t t = bag_stamp_ns(ds, i);
    const auto w = static_cast<std::uint32_t>(f.width), h = static_cast<std::uint32_t>(f.height);
    if (o.imu) write_base_imu(bag, f, t, true);
    bag.write("/tf", "tf2_msgs/TFMessage", ros1::kTfMessageMd5, t,
              ros1::tf_message(t, "odom", "base_link", *f.pose * mount.inverse()));
    bag.write("/camera/depth/camera_info", "sensor_msgs/CameraInfo", ros1::kCameraInfoMd5, t,
              ros1::camera_info(t, cam, w, h, f.intrinsics.fx, f.intrinsics.fy, f.intrinsics.cx, f.intrinsics.cy));
    if (o.compressed_depth) {
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
    if (o.colour)
      bag.write("/camera/color/image_raw", "sensor_msgs/Image", ros1::kImageMd5, t,
                ros1::image(t, "camera_color_optical_frame", w, h, "rgb8", w * 3, f.rgb));
    if (o.imu) write_base_imu(bag, f, t, false);
  }
}

}  // namespace tunnelmap::testing
