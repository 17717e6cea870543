#include "core/recordings/ros_messages.h"

#include <cmath>
#include <tuple>

#include "core/recordings/message_reader.h"

namespace tunnelmap::recordings {
namespace {

// ROS 1's std_msgs/Header starts with a sequence number that ROS 2 dropped.
RosHeader read_header(MessageReader& r, MessageEncoding e) {
  RosHeader h;
  if (e == MessageEncoding::Ros1) r.u32();
  h.stamp_ns = r.time_ns();
  h.frame_id = r.string();
  return h;
}

Eigen::Vector3d read_vector3(MessageReader& r) {
  const double x = r.f64(), y = r.f64(), z = r.f64();
  return {x, y, z};
}

// geometry_msgs/Quaternion is x, y, z, w; normalised since recorders round.
Eigen::Quaterniond read_quaternion(MessageReader& r) {
  const double x = r.f64(), y = r.f64(), z = r.f64(), w = r.f64();
  Eigen::Quaterniond q(w, x, y, z);
  const double n = q.norm();
  if (!(n > 1e-9) || !std::isfinite(n)) throw TruncatedData("quaternion of zero or invalid length");
  return q.normalized();
}

Eigen::Isometry3d read_rigid(MessageReader& r) {  // Transform or Pose: position then rotation
  const Eigen::Vector3d t = read_vector3(r);
  const Eigen::Quaterniond q = read_quaternion(r);
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = q.toRotationMatrix();
  iso.translation() = t;
  return iso;
}

RosTransform read_transform_stamped(MessageReader& r, MessageEncoding e) {
  RosTransform t;
  t.header = read_header(r, e);
  t.child_frame_id = r.string();
  t.transform = read_rigid(r);
  return t;
}

std::string strip_msg_infix(const std::string& type) {
  const auto p = type.find("/msg/");
  return p == std::string::npos ? type : type.substr(0, p) + "/" + type.substr(p + 5);
}

}  // namespace

RosType ros_type(const std::string& type_name) {
  const std::string t = strip_msg_infix(type_name);
  if (t == "sensor_msgs/Image") return RosType::Image;
  if (t == "sensor_msgs/CompressedImage") return RosType::CompressedImage;
  if (t == "sensor_msgs/CameraInfo") return RosType::CameraInfo;
  if (t == "tf2_msgs/TFMessage" || t == "tf/tfMessage") return RosType::TfMessage;
  if (t == "geometry_msgs/PoseStamped") return RosType::PoseStamped;
  if (t == "geometry_msgs/TransformStamped") return RosType::TransformStamped;
  if (t == "nav_msgs/Odometry") return RosType::Odometry;
  if (t == "sensor_msgs/Imu") return RosType::Imu;
  return RosType::Other;
}

const char* ros_type_label(RosType t) {
  switch (t) {
    case RosType::Image: return "sensor_msgs/Image";
    case RosType::CompressedImage: return "sensor_msgs/CompressedImage";
    case RosType::CameraInfo: return "sensor_msgs/CameraInfo";
    case RosType::TfMessage: return "tf2_msgs/TFMessage";
    case RosType::PoseStamped: return "geometry_msgs/PoseStamped";
    case RosType::TransformStamped: return "geometry_msgs/TransformStamped";
    case RosType::Odometry: return "nav_msgs/Odometry";
    case RosType::Imu: return "sensor_msgs/Imu";
    case RosType::Other: break;
  }
  return "other";
}

RosImage decode_image(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosImage img;
  img.header = read_header(r, e);
  img.height = r.u32();
  img.width = r.u32();
  img.encoding = r.string();
  img.big_endian = r.u8() != 0;
  img.step = r.u32();
  std::tie(img.data, img.size) = r.byte_sequence();
  return img;
}

RosCompressedImage decode_compressed_image(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosCompressedImage img;
  img.header = read_header(r, e);
  img.format = r.string();
  std::tie(img.data, img.size) = r.byte_sequence();
  return img;
}

RosCameraInfo decode_camera_info(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosCameraInfo info;
  info.header = read_header(r, e);
  info.height = r.u32();
  info.width = r.u32();
  info.distortion_model = r.string();
  info.d = r.f64_sequence();
  r.f64_array(info.k.data(), 9);
  r.f64_array(info.r.data(), 9);
  r.f64_array(info.p.data(), 12);
  return info;  // binning and region of interest are not used
}

std::vector<RosTransform> decode_tf_message(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  const std::uint32_t n = r.sequence_length();
  // Each transform takes at least 60 bytes: a corrupt count cannot reserve a huge vector.
  if (n > m.size / 60) throw TruncatedData("more transforms than the message can hold");
  std::vector<RosTransform> out;
  out.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) out.push_back(read_transform_stamped(r, e));
  return out;
}

RosTransform decode_transform_stamped(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  return read_transform_stamped(r, e);
}

RosTransform decode_pose_stamped(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosTransform t;
  t.header = read_header(r, e);
  t.transform = read_rigid(r);
  return t;
}

RosTransform decode_odometry(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosTransform t;
  t.header = read_header(r, e);
  t.child_frame_id = r.string();
  t.transform = read_rigid(r);  // pose.pose; its covariance and the twist follow
  return t;
}

RosImu decode_imu(const MessageView& m, MessageEncoding e) {
  MessageReader r(m.data, m.size, e);
  RosImu imu;
  imu.header = read_header(r, e);
  double skipped[9];
  r.f64_array(skipped, 4);  // orientation: zeros when the driver has none
  r.f64_array(skipped, 9);  // its covariance
  r.f64_array(skipped, 3);  // angular velocity
  r.f64_array(skipped, 9);  // its covariance
  const Eigen::Vector3d a = read_vector3(r);
  double covariance[9];
  r.f64_array(covariance, 9);
  if (covariance[0] != -1.0 && a.allFinite()) imu.linear_acceleration = a;
  return imu;
}

}  // namespace tunnelmap::recordings
