// `tunnelmap-cli topics`: the listing, its JSON, the suggested command for a recording with a
// depth camera, and one-line refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/core/recordings/recordings_fixture.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/cdr_writer.h"

namespace tunnelmap {
namespace {

using testing::run_cli;

TEST(TopicsCommand, ListsTypesCountsRatesAndUses) {
  SKIP_WITHOUT_RECORDINGS();
  testing::IoTempDir tmp;
  const std::string json_path = tmp.file("topics.json");
  const testing::CliRun r = run_cli("topics " + testing::recording("ros1_bag/rosbagjs_example-bz2.bag") + " --json " + json_path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("/tf                    tf/tfMessage             2688     125.04  tf"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no suggestion: no depth image topic"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(testing::slurp(json_path));
  EXPECT_EQ(j["format"], "ros1");
  EXPECT_EQ(j["message_count"], 8647);
  EXPECT_TRUE(j["suggested_command"].is_null());
  bool saw_tf_static = false;
  for (const auto& t : j["topics"]) {
    if (t["name"] != "/tf_static") continue;
    saw_tf_static = true;
    EXPECT_EQ(t["count"], 1);
    EXPECT_TRUE(t["rate_hz"].is_null());  // one message: no rate, not 0
    EXPECT_EQ(t["use"], "tf_static");
  }
  EXPECT_TRUE(saw_tf_static);
}

TEST(TopicsCommand, MarksARealImuTopic) {
  SKIP_WITHOUT_RECORDINGS();
  const testing::CliRun r = run_cli("topics " + testing::recording("ros1_bag/cartographer_b0-2014-07-21-12-42-53-tiny.bag"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("imu                  sensor_msgs/Imu                     1243     197.38  imu"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("no gravity:"), std::string::npos) << r.out;  // one IMU topic: it would be read
}

TEST(TopicsCommand, SuggestsTheDepthCameraCommandLine) {
  testing::IoTempDir tmp;
  const std::string bag = tmp.file("cam.mcap");
  testing::McapWriter w(bag, {});
  const std::vector<std::uint8_t> depth(8 * 6 * 2, 0), rgb(8 * 6 * 3, 0);
  for (int i = 0; i < 3; ++i) {
    const std::int64_t t = 1000000000LL * (10 + i);
    w.write("/cam/depth/camera_info", "sensor_msgs/msg/CameraInfo", t, testing::cdr_camera_info(t, "cam", 8, 6, 5, 5, 4, 3));
    w.write("/cam/color/camera_info", "sensor_msgs/msg/CameraInfo", t, testing::cdr_camera_info(t, "rgb", 8, 6, 5, 5, 4, 3));
    w.write("/cam/depth/image_raw", "sensor_msgs/msg/Image", t, testing::cdr_image(t, "cam", 8, 6, "16UC1", 16, depth));
    w.write("/cam/color/image_raw", "sensor_msgs/msg/Image", t, testing::cdr_image(t, "rgb", 8, 6, "rgb8", 24, rgb));
  }
  w.close();
  const testing::CliRun r = run_cli("topics " + bag);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("/cam/depth/image_raw    sensor_msgs/msg/Image              3       1.00  depth"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("suggested: tunnelmap-cli detect " + bag +
                       " --depth-topic /cam/depth/image_raw --color-topic /cam/color/image_raw"
                       " --camera-info-topic /cam/depth/camera_info"),
            std::string::npos)
      << r.out;
}

TEST(TopicsCommand, RefusesInOneLine) {
  SKIP_WITHOUT_RECORDINGS();
  const testing::CliRun wrong = run_cli("topics " + testing::recording("mcap/rosbag2_wrong_rmw_test/wrong_rmw_test_0.mcap"));
  EXPECT_EQ(wrong.exit_code, 3);
  EXPECT_EQ(testing::count_lines(wrong.err), 1) << wrong.err;
  EXPECT_NE(wrong.err.find("message encoding 'wrong_format' cannot be decoded"), std::string::npos) << wrong.err;
  testing::IoTempDir tmp;
  const std::string not_a_bag = tmp.file("x.mcap");
  std::ofstream(not_a_bag) << "hello";
  const testing::CliRun bad = run_cli("topics " + not_a_bag);
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(bad.err.find("not an MCAP file"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace tunnelmap
