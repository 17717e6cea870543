#pragma once
// The real ROS 1 bag writer (Debian's rosbag_storage) behind a plain interface, for the tests:
// messages are given already serialised in the ROS 1 wire format with their type and MD5 sum.
// Built in its own library (tests/CMakeLists.txt) so that only this file sees the ROS headers.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tunnelmap::testing {

class Ros1BagWriter {
 public:
  // compression: "none", "bz2" or "lz4". std::runtime_error when the bag cannot be opened.
  Ros1BagWriter(const std::string& path, const std::string& compression);
  ~Ros1BagWriter();  // closes the bag (writes its index)
  void write(const std::string& topic, const std::string& type, const std::string& md5sum, std::int64_t time_ns,
             const std::vector<std::uint8_t>& bytes);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tunnelmap::testing
