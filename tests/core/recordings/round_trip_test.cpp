// A simulated posed sequence written as an MCAP (zstd chunks) and as a rosbag2 .db3 (32FC1
// depth, camera info, colour, odometry) reads back as the same frames, and `detect` gives the
// same results on the recording as on the original dataset; `map` and `fuse` likewise.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/core/recordings/round_trip_support.h"
#include "tests/support/mcap_writer.h"
#include "tests/support/posed_bag.h"
#include "tests/support/rosbag2_db3_writer.h"

namespace tunnelmap {
namespace {

using testing::SimulatedSequence;
using testing::detect_json;
using testing::expect_same_detections;
using testing::expect_same_frames;

std::string write_mcap(const SimulatedSequence& seq, const std::string& compression) {
  const std::string path = seq.tmp.file("posed_" + compression + ".mcap");
  testing::McapWriter::Options o;
  o.compression = compression;
  o.chunk_bytes = 2 << 20;  // several chunks: the reader walks the chunk index
  testing::McapWriter w(path, o);
  testing::write_posed_bag(seq.ds, [&](const std::string& topic, const std::string& type, std::int64_t t,
                                       const std::vector<std::uint8_t>& cdr) {
    w.write(topic, type, static_cast<std::uint64_t>(t), cdr);
  });
  w.close();
  return path;
}

std::string write_db3(const SimulatedSequence& seq) {
  const std::string path = seq.tmp.file("posed.db3");
  testing::Rosbag2Db3Writer w(path);
  testing::write_posed_bag(seq.ds, [&](const std::string& topic, const std::string& type, std::int64_t t,
                                       const std::vector<std::uint8_t>& cdr) { w.write(topic, type, t, cdr); });
  return path;
}

TEST(RecordingRoundTrip, McapZstdReadsBackAsTheDataset) {
  const SimulatedSequence seq;
  const std::string bag = write_mcap(seq, "zstd");
  expect_same_frames(seq.ds, bag);
  const nlohmann::json original = detect_json(seq.tmp, seq.dataset_dir, "original");
  const nlohmann::json from_bag = detect_json(seq.tmp, bag, "bag");
  expect_same_detections(original, from_bag);
  std::size_t detected = 0;
  for (const auto& f : original["frames"]) detected += f["detected"].get<bool>();
  EXPECT_GT(detected, 0u);  // the comparison is between real detections
}

TEST(RecordingRoundTrip, McapLz4AndDb3ReadBackAsTheDataset) {
  const SimulatedSequence seq;
  expect_same_frames(seq.ds, write_mcap(seq, "lz4"));
  const std::string db3 = write_db3(seq);
  expect_same_frames(seq.ds, db3);
  expect_same_detections(detect_json(seq.tmp, seq.dataset_dir, "original"), detect_json(seq.tmp, db3, "db3"));
}

TEST(RecordingRoundTrip, MapAndConvertTakeTheBag) {
  const SimulatedSequence seq;
  const std::string bag = write_mcap(seq, "zstd");
  const nlohmann::json original = detect_json(seq.tmp, seq.dataset_dir, "map_original", "map");
  const nlohmann::json from_bag = detect_json(seq.tmp, bag, "map_bag", "map");
  ASSERT_EQ(original["frames"].size(), 4u);
  EXPECT_TRUE(original["frames"][0].contains("camera_to_world"));
  expect_same_detections(original, from_bag);

  const std::string tum = seq.tmp.file("tum");
  const testing::CliRun r = testing::run_cli("convert " + bag + " " + tum + " --to tum");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 4 frames (4 with colour, 4 with a pose)"), std::string::npos) << r.out;
  const Dataset converted = read_dataset(tum);
  ASSERT_EQ(converted.frames.size(), 4u);
  EXPECT_LT((converted.frames[3].pose->matrix() - seq.ds.frames[3].pose->matrix()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(RecordingRoundTrip, FuseTakesTheBag) {
  const SimulatedSequence seq;
  const std::string bag = write_db3(seq);
  const nlohmann::json original = detect_json(seq.tmp, seq.dataset_dir, "fuse_original", "fuse");
  ASSERT_EQ(original["frames"].size(), 4u);
  expect_same_detections(original, detect_json(seq.tmp, bag, "fuse_bag", "fuse"));
}

TEST(RecordingRoundTrip, Db3MapsAndMcapFusesAsTheDataset) {
  const SimulatedSequence seq;
  const nlohmann::json mapped = detect_json(seq.tmp, seq.dataset_dir, "map_original", "map");
  ASSERT_TRUE(mapped["frames"][0].contains("camera_to_world"));
  expect_same_detections(mapped, detect_json(seq.tmp, write_db3(seq), "map_db3", "map"));
  expect_same_detections(detect_json(seq.tmp, seq.dataset_dir, "fuse_original", "fuse"),
                         detect_json(seq.tmp, write_mcap(seq, "zstd"), "fuse_mcap", "fuse"));
}

TEST(RecordingRoundTrip, EveryAndDurationSelectFrames) {
  const SimulatedSequence seq;
  const std::string bag = write_mcap(seq, "");
  ReadOptions opt;
  opt.recording.every = 2;
  const auto every_other = open_input(bag, opt);
  ASSERT_EQ(every_other->size(), 2u);
  EXPECT_LT((every_other->load(1).pose->matrix() - seq.ds.load_frame(2).pose->matrix()).cwiseAbs().maxCoeff(), 1e-6);
  opt.recording.every = 1;
  opt.recording.start_s = 1e-3;  // past the first frame
  const auto later = open_input(bag, opt);
  EXPECT_EQ(later->size(), 3u);
}

}  // namespace
}  // namespace tunnelmap
