// A simulated posed sequence whose frames carry an IMU's gravity, written as robot recordings
// with the IMU's accelerometer at rest around each frame: in the camera's frame (MCAP, rosbag2
// .db3) or on the robot base behind a /tf_static mounting (ROS 1, the real writer). Each frame
// reads back with its gravity in the camera's frame, `convert` keeps it, `map` uses it as it
// does from the dataset, and the IMU topic is chosen as the other topics are.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/io/dataset.h"
#include "core/io/dataset_writer.h"
#include "core/io/frame_source.h"
#include "core/sim/sim_dataset_writer.h"
#include "tests/core/recordings/round_trip_support.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/posed_bag.h"
#include "tests/support/rosbag2_db3_writer.h"
#include "tests/support_ros1/posed_ros1_bag.h"

namespace tunnelmap {
namespace {

constexpr std::size_t kFrameWithoutImu = 2;

// Four frames 0.2 s apart (a robot scanning at its stops), their poses drifted, with an IMU's
// gravity but frame 2.
struct ImuSequence {
  testing::IoTempDir tmp;
  std::string dataset_dir = tmp.file("sim");
  Dataset ds;
  ImuSequence() {
    SimConfig config;
    config.frames = 4;
    config.frame_interval_s = 0.2;
    config.imu_gravity_deg = 0.3;
    config.drift_translation_mm_per_sqrt_m = 10.0;
    config.drift_rotation_deg_per_sqrt_m = 1.0;
    write_sim_dataset(dataset_dir, config);
    ds = read_dataset(dataset_dir);
    ds.frames[kFrameWithoutImu].gravity.reset();
  }
};

// The MCAP with the IMU, and optionally a second IMU topic with the same readings.
std::string write_mcap_with_imu(const ImuSequence& seq, const std::string& second_imu_topic = "") {
  const std::string path = seq.tmp.file("imu.mcap");
  testing::McapWriter w(path, testing::McapWriter::Options{});
  testing::write_posed_bag(
      seq.ds,
      [&](const std::string& topic, const std::string& type, std::int64_t t, const std::vector<std::uint8_t>& cdr) {
        w.write(topic, type, static_cast<std::uint64_t>(t), cdr);
        if (topic == testing::kBagImuTopic && !second_imu_topic.empty())
          w.write(second_imu_topic, type, static_cast<std::uint64_t>(t), cdr);
      },
      true);
  w.close();
  return path;
}

double angle_rad(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::acos(std::min(1.0, a.dot(b))); }

// Every frame's gravity as the dataset has it (1e-9 rad), frame 2 none; and the reader's note.
void expect_gravity_read_back(const Dataset& ds, const std::string& bag, const std::string& imu_topic) {
  std::vector<std::string> notes;
  ReadOptions opt;
  opt.note = [&](const std::string& line) { notes.push_back(line); };
  const auto source = open_input(bag, opt);
  ASSERT_EQ(source->size(), ds.frames.size());
  for (std::size_t i = 0; i < ds.frames.size(); ++i) {
    SCOPED_TRACE(i);
    const DepthFrame got = source->load(i);
    ASSERT_EQ(got.gravity.has_value(), i != kFrameWithoutImu);
    if (got.gravity) EXPECT_LT(angle_rad(*got.gravity, *ds.frames[i].gravity), 1e-9);
  }
  const std::string want = bag + ": gravity from " + imu_topic + " for 3 of 4 frames (the others:";
  EXPECT_NE(std::find_if(notes.begin(), notes.end(), [&](const std::string& n) { return n.rfind(want, 0) == 0; }),
            notes.end())
      << want;
}

TEST(ImuRoundTrip, AnImuInTheCamerasFrameGivesEachFrameItsGravity) {
  const ImuSequence seq;
  for (std::size_t i = 0; i < seq.ds.frames.size(); ++i)  // the simulated IMU is not the camera's up
    if (seq.ds.frames[i].gravity) EXPECT_GT(angle_rad(*seq.ds.frames[i].gravity, -Eigen::Vector3d::UnitY()), 1e-3);
  expect_gravity_read_back(seq.ds, write_mcap_with_imu(seq), testing::kBagImuTopic);
  const std::string db3 = seq.tmp.file("imu.db3");
  {
    testing::Rosbag2Db3Writer w(db3);
    testing::write_posed_bag(
        seq.ds,
        [&](const std::string& topic, const std::string& type, std::int64_t t, const std::vector<std::uint8_t>& cdr) {
          w.write(topic, type, t, cdr);
        },
        true);
  }
  expect_gravity_read_back(seq.ds, db3, testing::kBagImuTopic);
}

TEST(ImuRoundTrip, AnImuOnTheRobotBaseIsTurnedIntoTheCamerasFrameThroughTf) {
  const ImuSequence seq;
  const std::string bag = seq.tmp.file("imu.bag");
  testing::Ros1PosedBagOptions o;
  o.imu = true;
  testing::write_posed_ros1_bag(seq.ds, bag, o);
  expect_gravity_read_back(seq.ds, bag, "/imu/data");
}

TEST(ImuRoundTrip, ConvertKeepsTheGravityAndMapUsesItAsFromTheDataset) {
  const ImuSequence seq;
  const std::string bag = write_mcap_with_imu(seq);
  const std::string out = seq.tmp.file("converted");
  const testing::CliRun r = testing::run_cli("convert " + bag + " " + out + " --to dataset");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 4 frames (4 with colour, 4 with a pose, 3 with gravity)"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("gravity from /camera/imu for 3 of 4 frames"), std::string::npos) << r.err;
  const Dataset converted = read_dataset(out);
  for (std::size_t i = 0; i < 4; ++i) {
    ASSERT_EQ(converted.frames[i].gravity.has_value(), i != kFrameWithoutImu);
    if (i != kFrameWithoutImu) EXPECT_LT(angle_rad(*converted.frames[i].gravity, *seq.ds.frames[i].gravity), 1e-9);
  }

  // `map` from the recording gives the poses it gives from a dataset with the same gravity,
  // and the gravity moved them.
  write_dataset_folder(seq.ds, seq.tmp.file("with_gravity"), SequenceExport{});
  const nlohmann::json from_bag = testing::detect_json(seq.tmp, bag, "map_bag", "map");
  testing::expect_same_detections(testing::detect_json(seq.tmp, seq.tmp.file("with_gravity"), "map_dataset", "map"),
                                  from_bag);
  for (std::size_t i = 0; i < 4; ++i) {  // each frame says which gravity held its tilt
    const nlohmann::json& g = from_bag["frames"][i]["gravity"];
    ASSERT_EQ(g.is_null(), i == kFrameWithoutImu) << i;
    if (!g.is_null())
      EXPECT_LT(angle_rad(Eigen::Vector3d(g[0], g[1], g[2]), *seq.ds.frames[i].gravity), 1e-9) << i;
  }
  const nlohmann::json without = testing::detect_json(seq.tmp, bag, "map_bag_without", "map --imu-topic none");
  EXPECT_TRUE(without["frames"][0]["gravity"].is_null());
  double largest_change = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto a = from_bag["frames"][i]["camera_to_world"].flatten(), b = without["frames"][i]["camera_to_world"].flatten();
    for (auto it = a.begin(); it != a.end(); ++it)
      if (it->is_number()) largest_change = std::max(largest_change, std::abs(it->get<double>() - b[it.key()].get<double>()));
  }
  EXPECT_GT(largest_change, 1e-4);
}

TEST(ImuRoundTrip, SeveralImuTopicsAreReadOnlyWhenOneIsChosen) {
  const ImuSequence seq;
  const std::string bag = write_mcap_with_imu(seq, "/robot/imu");
  const std::string listing = seq.tmp.file("topics.json");
  ASSERT_EQ(testing::run_cli("topics " + bag + " --json " + listing).exit_code, 0);
  const nlohmann::json topics = nlohmann::json::parse(testing::slurp(listing));
  EXPECT_EQ(topics["imu_not_read_because"], "several IMU topics (/camera/imu, /robot/imu): choose one with --imu-topic");
  EXPECT_EQ(topics["suggested_command"].get<std::string>().find("--imu-topic"), std::string::npos);
  for (const auto& t : topics["topics"]) {
    if (t["name"] == "/robot/imu") EXPECT_EQ(t["use"], "imu");
  }

  const auto convert = [&](const std::string& name, const std::string& flags) {
    return testing::run_cli("convert " + bag + " " + seq.tmp.file(name) + " --to dataset" + flags);
  };
  const testing::CliRun none_chosen = convert("none_chosen", "");
  ASSERT_EQ(none_chosen.exit_code, 0) << none_chosen.err;
  EXPECT_NE(none_chosen.err.find("several IMU topics"), std::string::npos) << none_chosen.err;
  EXPECT_EQ(none_chosen.out.find("with gravity"), std::string::npos) << none_chosen.out;
  const testing::CliRun chosen = convert("chosen", " --imu-topic /robot/imu");
  ASSERT_EQ(chosen.exit_code, 0) << chosen.err;
  EXPECT_NE(chosen.out.find("3 with gravity"), std::string::npos) << chosen.out;
  const testing::CliRun off = convert("off", " --imu-topic none");
  EXPECT_EQ(off.out.find("with gravity"), std::string::npos) << off.out;
  const testing::CliRun missing = convert("missing", " --imu-topic /nope");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find(bag), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("no topic /nope (--imu-topic)"), std::string::npos) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(seq.tmp.file("missing")));
}

}  // namespace
}  // namespace tunnelmap
