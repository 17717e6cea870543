#pragma once
// Serialises ROS 2 messages as CDR (little-endian XCDR1, as rmw writes them) for the tests'
// bag writers: the 4-byte encapsulation header, fields aligned to their size, NUL-terminated
// strings. The mirror of core/recordings/message_reader.
#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace tunnelmap::testing {

class CdrWriter {
 public:
  CdrWriter() : buf_{0x00, 0x01, 0x00, 0x00} {}
  const std::vector<std::uint8_t>& bytes() const { return buf_; }

  void u8(std::uint8_t v) { buf_.push_back(v); }
  void u32(std::uint32_t v) { put(v); }
  void i32(std::int32_t v) { put(v); }
  void f64(double v) { put(v); }
  void string(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    buf_.insert(buf_.end(), s.begin(), s.end());
    buf_.push_back(0);
  }
  void bytes(const std::vector<std::uint8_t>& b) {
    u32(static_cast<std::uint32_t>(b.size()));
    buf_.insert(buf_.end(), b.begin(), b.end());
  }
  void header(std::int64_t stamp_ns, const std::string& frame_id) {
    i32(static_cast<std::int32_t>(stamp_ns / 1000000000));
    u32(static_cast<std::uint32_t>(stamp_ns % 1000000000));
    string(frame_id);
  }
  void pose(const Eigen::Isometry3d& T) {  // Point then Quaternion (x, y, z, w)
    const Eigen::Quaterniond q(T.rotation());
    for (double v : {T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(), q.w()}) f64(v);
  }

 private:
  template <typename T>
  void put(T v) {
    while ((buf_.size() - 4) % sizeof(T)) buf_.push_back(0);  // aligned after the header
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    buf_.insert(buf_.end(), b, b + sizeof(T));
  }
  std::vector<std::uint8_t> buf_;
};

// sensor_msgs/msg/Image
inline std::vector<std::uint8_t> cdr_image(std::int64_t stamp_ns, const std::string& frame, std::uint32_t width,
                                           std::uint32_t height, const std::string& encoding, std::uint32_t step,
                                           const std::vector<std::uint8_t>& data) {
  CdrWriter w;
  w.header(stamp_ns, frame);
  w.u32(height);
  w.u32(width);
  w.string(encoding);
  w.u8(0);
  w.u32(step);
  w.bytes(data);
  return w.bytes();
}

// sensor_msgs/msg/CameraInfo with K = [fx 0 cx; 0 fy cy; 0 0 1] and distortion d.
inline std::vector<std::uint8_t> cdr_camera_info(std::int64_t stamp_ns, const std::string& frame, std::uint32_t width,
                                                 std::uint32_t height, double fx, double fy, double cx, double cy,
                                                 const std::vector<double>& d = {}) {
  CdrWriter w;
  w.header(stamp_ns, frame);
  w.u32(height);
  w.u32(width);
  w.string(d.empty() ? "" : "plumb_bob");
  w.u32(static_cast<std::uint32_t>(d.size()));
  for (double v : d) w.f64(v);
  for (double v : {fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0}) w.f64(v);              // k
  for (double v : {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) w.f64(v);          // r
  for (double v : {fx, 0.0, cx, 0.0, 0.0, fy, cy, 0.0, 0.0, 0.0, 1.0, 0.0}) w.f64(v);  // p
  for (int i = 0; i < 6; ++i) w.u32(0);  // binning x, y; roi x, y, height, width
  w.u8(0);                               // roi do_rectify
  return w.bytes();
}

// nav_msgs/msg/Odometry: parent <- child pose, zero covariance and twist.
inline std::vector<std::uint8_t> cdr_odometry(std::int64_t stamp_ns, const std::string& parent,
                                              const std::string& child, const Eigen::Isometry3d& T) {
  CdrWriter w;
  w.header(stamp_ns, parent);
  w.string(child);
  w.pose(T);
  for (int i = 0; i < 36 + 6 + 36; ++i) w.f64(0.0);  // pose covariance, twist, twist covariance
  return w.bytes();
}

// sensor_msgs/msg/Imu with only its accelerometer (orientation and gyro marked unknown), or
// with none (a gyro-only topic: linear_acceleration_covariance[0] = -1).
inline std::vector<std::uint8_t> cdr_imu(std::int64_t stamp_ns, const std::string& frame,
                                         const Eigen::Vector3d& specific_force, bool has_accelerometer = true) {
  CdrWriter w;
  w.header(stamp_ns, frame);
  for (int i = 0; i < 4; ++i) w.f64(0.0);                                 // orientation
  for (int i = 0; i < 9; ++i) w.f64(i == 0 ? -1.0 : 0.0);                 // its covariance
  for (int i = 0; i < 3; ++i) w.f64(0.0);                                 // angular velocity
  for (int i = 0; i < 9; ++i) w.f64(i == 0 ? -1.0 : 0.0);                 // its covariance
  for (int i = 0; i < 3; ++i) w.f64(specific_force[i]);                   // linear acceleration
  for (int i = 0; i < 9; ++i) w.f64(i == 0 && !has_accelerometer ? -1.0 : 0.0);
  return w.bytes();
}

}  // namespace tunnelmap::testing
