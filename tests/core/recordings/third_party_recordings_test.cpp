// Every third-party recording lists its topics with the types and counts its SOURCES.md
// inventory gives, or is refused with one line naming the problem (the wrong-encoding bags).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "core/recordings/recording.h"
#include "core/util/error.h"
#include "tests/core/recordings/recordings_fixture.h"

namespace tunnelmap {
namespace {

using recordings::open_recording;
using testing::recording;
using testing::recordings_dir;

struct ExpectedTopic {
  std::string name, type;  // type empty: SOURCES.md does not name it
  std::uint64_t count;
};

struct ExpectedRecording {
  std::string path;  // relative to the recordings folder
  std::size_t topics, messages, files;
  std::vector<ExpectedTopic> listed;
};

// Transcribed from SOURCES.md.
const std::vector<ExpectedRecording>& expected() {
  static const std::vector<ExpectedTopic> rosbags_rs = {
      {"/test/sensor_msgs/image", "sensor_msgs/msg/Image", 2},
      {"/test/sensor_msgs/camera_info", "sensor_msgs/msg/CameraInfo", 2},
      {"/test/sensor_msgs/compressed_image", "sensor_msgs/msg/CompressedImage", 2},
      {"/test/tf2_msgs/tf_message", "tf2_msgs/msg/TFMessage", 2},
      {"/test/geometry_msgs/pose_stamped", "geometry_msgs/msg/PoseStamped", 2},
      {"/test/geometry_msgs/transform_stamped", "geometry_msgs/msg/TransformStamped", 2},
      {"/test/nav_msgs/odometry", "nav_msgs/msg/Odometry", 2},
      {"/test/sensor_msgs/point_cloud2", "sensor_msgs/msg/PointCloud2", 2},
      {"/test/stereo_msgs/disparity_image", "stereo_msgs/msg/DisparityImage", 2}};
  static const std::vector<ExpectedTopic> cdr_test = {{"/test_topic", "test_msgs/msg/BasicTypes", 3},
                                                      {"/array_topic", "test_msgs/msg/Arrays", 4}};
  static const std::vector<ExpectedTopic> services = {
      {"/test_topic1", "test_msgs/msg/Strings", 1},
      {"/test_topic2", "test_msgs/msg/Strings", 1},
      {"/test_service1/_service_event", "test_msgs/srv/BasicTypes_Event", 4},
      {"/test_service2/_service_event", "test_msgs/srv/BasicTypes_Event", 4},
      {"/events/write_split", "", 0}};
  static const std::vector<ExpectedTopic> talker = {{"/topic", "std_msgs/msg/String", 10},
                                                    {"/rosout", "rcl_interfaces/msg/Log", 10},
                                                    {"/parameter_events", "", 0}};
  static const std::vector<ExpectedTopic> rewriter = {{"a_empty", "test_msgs/msg/Empty", 100},
                                                      {"b_basictypes", "test_msgs/msg/BasicTypes", 50}};
  static const std::vector<ExpectedTopic> seek = {{"topic1", "test_msgs/BasicTypes", 5}};
  static const std::vector<ExpectedTopic> wbag = {
      {"AAA", "std_msgs/msg/String", 804}, {"HHH", "std_msgs/msg/String", 726}};
  static const std::vector<ExpectedTopic> turtles = {{"/tf", "tf/tfMessage", 2688},
                                                     {"/tf_static", "tf2_msgs/TFMessage", 1},
                                                     {"/turtle1/pose", "turtlesim/Pose", 1344},
                                                     {"/turtle1/cmd_vel", "geometry_msgs/Twist", 357},
                                                     {"/turtle1/color_sensor", "turtlesim/Color", 1351},
                                                     {"/rosout", "rosgraph_msgs/Log", 10}};
  static const std::vector<ExpectedRecording> all = {
      {"mcap/rosbags-rs_test_bag_mcap", 94, 188, 1, rosbags_rs},
      {"mcap/rosbag2_cdr_test", 2, 7, 1, cdr_test},
      {"mcap/rosbag2_bag_with_topics_and_service_events", 5, 10, 1, services},
      {"mcap/rosbag2_talker", 3, 20, 1, talker},
      {"mcap/rosbag2_rewriter_a", 2, 150, 1, rewriter},
      {"mcap/rosbag2_test_bag_for_seek", 1, 5, 1, seek},
      {"mcap/rosbag2_wbag", 8, 6074, 5, wbag},
      {"rosbag2_sqlite3/rosbags-rs_test_bag_sqlite3", 94, 188, 1, rosbags_rs},
      {"rosbag2_sqlite3/rosbag2_cdr_test", 2, 7, 1, cdr_test},
      {"rosbag2_sqlite3/rosbag2_bag_with_topics_and_service_events", 5, 10, 1, services},
      {"rosbag2_sqlite3/rosbag2_talker", 3, 20, 1, talker},
      {"rosbag2_sqlite3/rosbag2_rewriter_a", 2, 150, 1, rewriter},
      {"rosbag2_sqlite3/rosbag2_test_bag_for_seek", 1, 5, 1, seek},
      {"rosbag2_sqlite3/rosbag2_wbag", 8, 6074, 5, wbag},
      {"rosbag2_sqlite3/rosbag2_empty_bag", 2, 0, 1, {{"/rosout", "", 0}, {"/parameter_events", "", 0}}},
      {"ros1_bag/ros_numpy_test.bag", 9, 9, 1,
       {{"/image", "sensor_msgs/Image", 1},
        {"/compressedimage", "sensor_msgs/CompressedImage", 1},
        {"/pointcloud", "sensor_msgs/PointCloud2", 1},
        {"/occupancygrid", "nav_msgs/OccupancyGrid", 1},
        {"/transform", "geometry_msgs/Transform", 1},
        {"/pose", "geometry_msgs/Pose", 1},
        {"/point", "geometry_msgs/Point", 1},
        {"/vector3", "geometry_msgs/Vector3", 1},
        {"/quaternion", "geometry_msgs/Quaternion", 1}}},
      {"ros1_bag/rosbagjs_example.bag", 9, 8647, 1, turtles},
      {"ros1_bag/rosbagjs_example-bz2.bag", 9, 8647, 1, turtles},
      {"ros1_bag/rosbagjs_example-lz4.bag", 9, 8647, 1, turtles},
      {"ros1_bag/rosbagjs_example-unsorted-chunks.bag", 1, 3, 1, {{"foo", "std_msgs/String", 3}}},
      {"ros1_bag/rosbagjs_no-messages.bag", 0, 0, 1, {}},
      {"ros1_bag/embag_test.bag", 3, 15, 1,
       {{"/base_pose_ground_truth", "nav_msgs/Odometry", 5},
        {"/base_scan", "sensor_msgs/LaserScan", 5},
        {"/luminar_pointcloud", "sensor_msgs/PointCloud2", 5}}},
      {"ros1_bag/embag_test_2.bag", 1, 2, 1, {{"chatter", "std_msgs/String", 2}}},
      {"ros1_bag/embag_array_test.bag", 1, 20, 1, {{"/array_test", "basic_msgs/Arrays", 20}}},
      {"ros1_bag/cartographer_b0-2014-07-21-12-42-53-tiny.bag", 2, 1465, 1,
       {{"imu", "sensor_msgs/Imu", 1243}, {"horizontal_laser_2d", "sensor_msgs/MultiEchoLaserScan", 222}}},
  };
  return all;
}

const std::set<std::string>& refused() {
  static const std::set<std::string> r = {"mcap/rosbag2_wrong_rmw_test", "rosbag2_sqlite3/rosbag2_wrong_rmw_test"};
  return r;
}

TEST(ThirdPartyRecordings, EachListsItsTopicsTypesAndCounts) {
  SKIP_WITHOUT_RECORDINGS();
  for (const ExpectedRecording& e : expected()) {
    SCOPED_TRACE(e.path);
    const auto rec = open_recording(recording(e.path));
    const recordings::RecordingSummary& s = rec->summary();
    EXPECT_EQ(s.topics.size(), e.topics);
    EXPECT_EQ(s.message_count(), e.messages);
    EXPECT_EQ(s.files.size(), e.files);
    EXPECT_FALSE(s.truncation_note.has_value());
    for (const ExpectedTopic& t : e.listed) {
      const recordings::TopicInfo* found = s.topic(t.name);
      ASSERT_NE(found, nullptr) << t.name;
      EXPECT_EQ(found->message_count, t.count) << t.name;
      if (!t.type.empty()) EXPECT_EQ(found->type, t.type) << t.name;
    }
  }
}

TEST(ThirdPartyRecordings, ReadingDeliversEveryCountedMessage) {
  SKIP_WITHOUT_RECORDINGS();
  for (const ExpectedRecording& e : expected()) {
    SCOPED_TRACE(e.path);
    const auto rec = open_recording(recording(e.path));
    std::map<std::string, std::uint64_t> read;
    rec->read_messages({}, [&](const recordings::MessageView& m) {
      ++read[m.topic];
      return true;
    });
    for (const recordings::TopicInfo& t : rec->summary().topics)
      EXPECT_EQ(read[t.name], t.message_count) << t.name;
  }
}

TEST(ThirdPartyRecordings, WrongEncodingBagsAreRefusedInOneLine) {
  SKIP_WITHOUT_RECORDINGS();
  for (const std::string& path : refused()) {
    SCOPED_TRACE(path);
    try {
      open_recording(recording(path));
      ADD_FAILURE() << "opened";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("wrong_format"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

// A file added to the folder without an expectation here fails this test.
TEST(ThirdPartyRecordings, EveryRecordingInTheFolderIsCovered) {
  SKIP_WITHOUT_RECORDINGS();
  std::set<std::string> covered = refused();
  for (const ExpectedRecording& e : expected()) covered.insert(e.path);
  std::size_t seen = 0;
  for (const char* group : {"mcap", "rosbag2_sqlite3", "ros1_bag"})
    for (const auto& entry : std::filesystem::directory_iterator(recordings_dir() / group)) {
      const std::string rel = std::string(group) + "/" + entry.path().filename().string();
      EXPECT_TRUE(covered.count(rel)) << rel << " has no expectation";
      ++seen;
    }
  EXPECT_EQ(seen, covered.size());
}

}  // namespace
}  // namespace tunnelmap
