#pragma once
// The ROS messages TunnelMap reads from a recording, decoded from CDR (ROS 2) or the ROS 1
// wire format: sensor_msgs/Image, CompressedImage and CameraInfo, tf2_msgs/TFMessage (and
// ROS 1 tf/tfMessage), geometry_msgs/PoseStamped and TransformStamped, nav_msgs/Odometry,
// sensor_msgs/Imu.
// Only the fields used are kept. Decoders throw TruncatedData on a malformed message.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/recordings/recording.h"

namespace tunnelmap::recordings {

struct RosHeader {
  std::int64_t stamp_ns = 0;
  std::string frame_id;
};

struct RosImage {
  RosHeader header;
  std::uint32_t height = 0, width = 0, step = 0;
  std::string encoding;
  bool big_endian = false;
  const std::uint8_t* data = nullptr;  // points into the message bytes
  std::size_t size = 0;
};

struct RosCompressedImage {
  RosHeader header;
  std::string format;  // "png", "jpeg", "16UC1; compressedDepth png", ...
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

struct RosCameraInfo {
  RosHeader header;
  std::uint32_t height = 0, width = 0;
  std::string distortion_model;
  std::vector<double> d;
  std::array<double, 9> k{};
  std::array<double, 9> r{};
  std::array<double, 12> p{};
};

// A rigid transform with its frames: parent (header.frame_id) <- child, i.e. it maps points
// of the child frame into the parent frame.
struct RosTransform {
  RosHeader header;
  std::string child_frame_id;
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
};

// sensor_msgs/Imu's accelerometer: the specific force in m/s² (REP 145: gravity included, so
// at rest it points up). Absent when the driver marks it unknown (covariance[0] = -1, as a
// gyro-only topic does).
struct RosImu {
  RosHeader header;
  std::optional<Eigen::Vector3d> linear_acceleration;
};

enum class RosType { Image, CompressedImage, CameraInfo, TfMessage, PoseStamped, TransformStamped,
                     Odometry, Imu, Other };

// Maps "sensor_msgs/msg/Image", "sensor_msgs/Image" (ROS 1, or ROS 2 without /msg/), and
// "tf/tfMessage" to the types above.
RosType ros_type(const std::string& type_name);
const char* ros_type_label(RosType t);  // "sensor_msgs/Image", ...

RosImage decode_image(const MessageView& m, MessageEncoding e);
RosCompressedImage decode_compressed_image(const MessageView& m, MessageEncoding e);
RosCameraInfo decode_camera_info(const MessageView& m, MessageEncoding e);
std::vector<RosTransform> decode_tf_message(const MessageView& m, MessageEncoding e);
RosTransform decode_transform_stamped(const MessageView& m, MessageEncoding e);
// PoseStamped and Odometry as a transform header.frame_id <- (child_frame_id or "").
RosTransform decode_pose_stamped(const MessageView& m, MessageEncoding e);
RosTransform decode_odometry(const MessageView& m, MessageEncoding e);
RosImu decode_imu(const MessageView& m, MessageEncoding e);

}  // namespace tunnelmap::recordings
