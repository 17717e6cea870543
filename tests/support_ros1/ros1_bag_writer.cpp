#include "tests/support_ros1/ros1_bag_writer.h"

#include <rosbag/bag.h>

#include <cstring>

namespace tunnelmap::testing {

// A message already in the ROS 1 wire format: its traits come from the value, not the type.
struct RawRos1Message {
  std::string type, md5sum;
  const std::vector<std::uint8_t>* bytes = nullptr;
};

}  // namespace tunnelmap::testing

namespace ros::message_traits {
template <>
struct MD5Sum<tunnelmap::testing::RawRos1Message> {
  static const char* value(const tunnelmap::testing::RawRos1Message& m) { return m.md5sum.c_str(); }
  static const char* value() { return "*"; }
};
template <>
struct DataType<tunnelmap::testing::RawRos1Message> {
  static const char* value(const tunnelmap::testing::RawRos1Message& m) { return m.type.c_str(); }
  static const char* value() { return "*"; }
};
template <>
struct Definition<tunnelmap::testing::RawRos1Message> {
  static const char* value(const tunnelmap::testing::RawRos1Message&) { return ""; }
  static const char* value() { return ""; }
};
}  // namespace ros::message_traits

namespace ros::serialization {
template <>
struct Serializer<tunnelmap::testing::RawRos1Message> {
  template <typename Stream>
  static void write(Stream& stream, const tunnelmap::testing::RawRos1Message& m) {
    std::memcpy(stream.advance(static_cast<std::uint32_t>(m.bytes->size())), m.bytes->data(), m.bytes->size());
  }
  template <typename Stream>
  static void read(Stream&, tunnelmap::testing::RawRos1Message&) {}
  static std::uint32_t serializedLength(const tunnelmap::testing::RawRos1Message& m) {
    return static_cast<std::uint32_t>(m.bytes->size());
  }
};
}  // namespace ros::serialization

namespace tunnelmap::testing {

struct Ros1BagWriter::Impl {
  rosbag::Bag bag;
};

Ros1BagWriter::Ros1BagWriter(const std::string& path, const std::string& compression)
    : impl_(std::make_unique<Impl>()) {
  impl_->bag.open(path, rosbag::bagmode::Write);
  impl_->bag.setCompression(compression == "bz2"   ? rosbag::compression::BZ2
                            : compression == "lz4" ? rosbag::compression::LZ4
                                                   : rosbag::compression::Uncompressed);
}

Ros1BagWriter::~Ros1BagWriter() { impl_->bag.close(); }

void Ros1BagWriter::write(const std::string& topic, const std::string& type, const std::string& md5sum,
                          std::int64_t time_ns, const std::vector<std::uint8_t>& bytes) {
  ros::Time t;
  t.fromNSec(static_cast<std::uint64_t>(time_ns));
  impl_->bag.write(topic, t, RawRos1Message{type, md5sum, &bytes});
}

}  // namespace tunnelmap::testing
