#pragma once
// Serialises ROS 1 messages in their wire format (packed little-endian, u32-prefixed strings
// and arrays, std_msgs/Header with a seq) for the tests' ROS 1 bags, with each type's MD5 sum
// as rosbag records it.
#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace tunnelmap::testing::ros1 {

inline constexpr const char* kImageMd5 = "060021388200f6f0f447d0fcd9c64743";
inline constexpr const char* kCompressedImageMd5 = "8f7a12909da2c9d3332d540a0977563f";
inline constexpr const char* kCameraInfoMd5 = "c9a58c1b0b154e0e6da7578cb991d214";
inline constexpr const char* kTfMessageMd5 = "94810edda583a504dfda3829e70d7eec";
inline constexpr const char* kImuMd5 = "6a62c6daae103f4ff57a132d6f95cec2";

class Ros1Writer {
 public:
  const std::vector<std::uint8_t>& bytes() const { return buf_; }
  template <typename T>
  void put(T v) {
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    buf_.insert(buf_.end(), b, b + sizeof(T));
  }
  void string(const std::string& s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size()));
    buf_.insert(buf_.end(), s.begin(), s.end());
  }
  void bytes(const std::vector<std::uint8_t>& b) {
    put<std::uint32_t>(static_cast<std::uint32_t>(b.size()));
    buf_.insert(buf_.end(), b.begin(), b.end());
  }
  void header(std::int64_t stamp_ns, const std::string& frame) {
    put<std::uint32_t>(0);  // seq
    put<std::uint32_t>(static_cast<std::uint32_t>(stamp_ns / 1000000000));
    put<std::uint32_t>(static_cast<std::uint32_t>(stamp_ns % 1000000000));
    string(frame);
  }

 private:
  std::vector<std::uint8_t> buf_;
};

inline std::vector<std::uint8_t> image(std::int64_t t, const std::string& frame, std::uint32_t w, std::uint32_t h,
                                       const std::string& encoding, std::uint32_t step,
                                       const std::vector<std::uint8_t>& data) {
  Ros1Writer m;
  m.header(t, frame);
  m.put<std::uint32_t>(h);
  m.put<std::uint32_t>(w);
  m.string(encoding);
  m.put<std::uint8_t>(0);
  m.put<std::uint32_t>(step);
  m.bytes(data);
  return m.bytes();
}

inline std::vector<std::uint8_t> compressed_image(std::int64_t t, const std::string& frame, const std::string& format,
                                                  const std::vector<std::uint8_t>& data) {
  Ros1Writer m;
  m.header(t, frame);
  m.string(format);
  m.bytes(data);
  return m.bytes();
}

inline std::vector<std::uint8_t> camera_info(std::int64_t t, const std::string& frame, std::uint32_t w, std::uint32_t h,
                                             double fx, double fy, double cx, double cy) {
  Ros1Writer m;
  m.header(t, frame);
  m.put<std::uint32_t>(h);
  m.put<std::uint32_t>(w);
  m.string("plumb_bob");
  m.put<std::uint32_t>(5);
  for (int i = 0; i < 5; ++i) m.put<double>(0.0);  // no distortion
  for (double v : {fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0}) m.put<double>(v);
  for (double v : {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) m.put<double>(v);
  for (double v : {fx, 0.0, cx, 0.0, 0.0, fy, cy, 0.0, 0.0, 0.0, 1.0, 0.0}) m.put<double>(v);
  for (int i = 0; i < 6; ++i) m.put<std::uint32_t>(0);  // binning, roi
  m.put<std::uint8_t>(0);
  return m.bytes();
}

// tf2_msgs/TFMessage with one transform parent <- child.
inline std::vector<std::uint8_t> tf_message(std::int64_t t, const std::string& parent, const std::string& child,
                                            const Eigen::Isometry3d& T) {
  Ros1Writer m;
  m.put<std::uint32_t>(1);
  m.header(t, parent);
  m.string(child);
  const Eigen::Quaterniond q(T.rotation());
  for (double v : {T.translation().x(), T.translation().y(), T.translation().z(), q.x(), q.y(), q.z(), q.w()})
    m.put<double>(v);
  return m.bytes();
}

// sensor_msgs/Imu with only its accelerometer (orientation and gyro marked unknown).
inline std::vector<std::uint8_t> imu(std::int64_t t, const std::string& frame, const Eigen::Vector3d& specific_force) {
  Ros1Writer m;
  m.header(t, frame);
  for (int i = 0; i < 4; ++i) m.put<double>(0.0);                  // orientation
  for (int i = 0; i < 9; ++i) m.put<double>(i == 0 ? -1.0 : 0.0);  // its covariance
  for (int i = 0; i < 3; ++i) m.put<double>(0.0);                  // angular velocity
  for (int i = 0; i < 9; ++i) m.put<double>(i == 0 ? -1.0 : 0.0);  // its covariance
  for (int i = 0; i < 3; ++i) m.put<double>(specific_force[i]);    // linear acceleration
  for (int i = 0; i < 9; ++i) m.put<double>(0.0);
  return m.bytes();
}

}  // namespace tunnelmap::testing::ros1
