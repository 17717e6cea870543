// Messages of the third-party recordings decode to the values their SOURCES.md inventory
// gives, in CDR (MCAP, sqlite3) and in the ROS 1 format; a cut bag reads up to its last whole
// message and says so.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/recordings/byte_cursor.h"
#include "core/recordings/depth_image_decode.h"
#include "core/recordings/recording.h"
#include "core/recordings/ros_messages.h"
#include "tests/core/recordings/recordings_fixture.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using namespace recordings;

// Calls `use` with the first message of `topic`.
template <typename Use>
void first_message(const std::string& file, const std::string& topic, Use&& use) {
  const auto rec = open_recording(testing::recording(file));
  bool seen = false;
  rec->read_messages({topic}, [&](const MessageView& m) {
    use(m, rec->summary().encoding);
    seen = true;
    return false;
  });
  ASSERT_TRUE(seen) << topic;
}

TEST(RecordingMessages, CdrCameraInfoTfAndOdometry) {
  SKIP_WITHOUT_RECORDINGS();
  for (const char* file : {"mcap/rosbags-rs_test_bag_mcap", "rosbag2_sqlite3/rosbags-rs_test_bag_sqlite3"}) {
    SCOPED_TRACE(file);
    first_message(file, "/test/sensor_msgs/camera_info", [](const MessageView& m, MessageEncoding e) {
      const RosCameraInfo info = decode_camera_info(m, e);
      EXPECT_EQ(info.width, 640u);
      EXPECT_EQ(info.height, 480u);
      EXPECT_EQ(info.distortion_model, "plumb_bob");
      EXPECT_EQ(info.k, (std::array<double, 9>{525, 0, 320, 0, 525, 240, 0, 0, 1}));
      EXPECT_EQ(info.d, (std::vector<double>{0.1, -0.2, 0.001, 0.002, 0}));
    });
    first_message(file, "/test/tf2_msgs/tf_message", [](const MessageView& m, MessageEncoding e) {
      const std::vector<RosTransform> tf = decode_tf_message(m, e);
      ASSERT_EQ(tf.size(), 1u);
      EXPECT_EQ(tf[0].header.frame_id, "test_frame");
      EXPECT_EQ(tf[0].child_frame_id, "child_frame");
      EXPECT_EQ(tf[0].transform.translation(), Eigen::Vector3d(1, 2, 3));
      EXPECT_TRUE(tf[0].transform.linear().isIdentity(0));
    });
    first_message(file, "/test/geometry_msgs/transform_stamped", [](const MessageView& m, MessageEncoding e) {
      EXPECT_EQ(decode_transform_stamped(m, e).transform.translation(), Eigen::Vector3d(1, 2, 3));
    });
    first_message(file, "/test/geometry_msgs/pose_stamped", [](const MessageView& m, MessageEncoding e) {
      EXPECT_EQ(decode_pose_stamped(m, e).header.frame_id, "test_frame");
    });
  }
}

TEST(RecordingMessages, SyntheticImageIsInconsistentAndRefused) {
  SKIP_WITHOUT_RECORDINGS();
  first_message("mcap/rosbags-rs_test_bag_mcap", "/test/sensor_msgs/image", [](const MessageView& m, MessageEncoding e) {
    const RosImage img = decode_image(m, e);
    EXPECT_EQ(img.encoding, "rgb8");
    EXPECT_EQ(img.size, 30u);
    int w = 0, h = 0;
    try {
      decode_color_image(img, w, h);
      ADD_FAILURE() << "accepted";
    } catch (const TruncatedData& err) {
      EXPECT_NE(std::string(err.what()).find("holds 30 data bytes, needs 921600"), std::string::npos) << err.what();
    }
  });
}

TEST(RecordingMessages, Ros1ImageAndOdometry) {
  SKIP_WITHOUT_RECORDINGS();
  first_message("ros1_bag/ros_numpy_test.bag", "/image", [](const MessageView& m, MessageEncoding e) {
    const RosImage img = decode_image(m, e);
    int w = 0, h = 0;
    const std::vector<std::uint8_t> rgb = decode_color_image(img, w, h);
    EXPECT_EQ(w, 360);
    EXPECT_EQ(h, 240);
    EXPECT_EQ(rgb.size(), 259200u);
  });
  first_message("ros1_bag/embag_test.bag", "/base_pose_ground_truth", [](const MessageView& m, MessageEncoding e) {
    const RosTransform odom = decode_odometry(m, e);
    EXPECT_EQ(odom.header.frame_id, "odom");
    EXPECT_TRUE(odom.transform.matrix().allFinite());
  });
}

// The first `bytes` of a recording, as a robot losing power leaves it.
std::string cut_copy(const testing::IoTempDir& tmp, const std::string& file, std::size_t bytes) {
  const std::string cut = tmp.file("cut" + std::filesystem::path(file).extension().string());
  std::ifstream in(testing::recording(file), std::ios::binary);
  std::vector<char> head(bytes);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  std::ofstream(cut, std::ios::binary).write(head.data(), in.gcount());
  return cut;
}

// The uncompressed turtlesim bag cut in its only chunk: the messages before the cut are read.
TEST(RecordingMessages, TruncatedBagReadsUpToItsLastWholeMessage) {
  SKIP_WITHOUT_RECORDINGS();
  testing::IoTempDir tmp;
  const auto rec = open_recording(cut_copy(tmp, "ros1_bag/rosbagjs_example.bag", 500000));
  ASSERT_TRUE(rec->summary().truncation_note.has_value());
  EXPECT_NE(rec->summary().truncation_note->find("last whole message"), std::string::npos);
  const std::uint64_t counted = rec->summary().message_count();
  EXPECT_GT(counted, 4000u);
  EXPECT_LT(counted, 8647u);
  std::uint64_t read = 0;
  rec->read_messages({}, [&](const MessageView&) { return ++read > 0; });
  EXPECT_EQ(read, counted);
}

// rosbag2's cdr_test MCAP (one uncompressed chunk of 7 messages) cut inside its chunk.
TEST(RecordingMessages, TruncatedMcapReadsUpToItsLastWholeMessage) {
  SKIP_WITHOUT_RECORDINGS();
  testing::IoTempDir tmp;
  const auto rec = open_recording(cut_copy(tmp, "mcap/rosbag2_cdr_test/cdr_test_0.mcap", 6000));
  ASSERT_TRUE(rec->summary().truncation_note.has_value());
  EXPECT_EQ(rec->summary().message_count(), 6u);
  std::uint64_t read = 0;
  rec->read_messages({}, [&](const MessageView&) { return ++read > 0; });
  EXPECT_EQ(read, 6u);
}

}  // namespace
}  // namespace tunnelmap
