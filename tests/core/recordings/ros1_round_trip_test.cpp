// The simulated posed sequence written as ROS 1 bags by the real writer (rosbag_storage):
// 16UC1 or compressedDepth depth, camera info, colour, the camera pose as /tf odom <- base_link
// over a /tf_static base_link <- camera. Each reads back as the dataset's frames, and `detect`,
// `map` and `fuse` give the dataset's results.
#include <gtest/gtest.h>

#include "tests/core/recordings/round_trip_support.h"
#include "tests/support_ros1/posed_ros1_bag.h"

namespace tunnelmap {
namespace {

using testing::SimulatedSequence;

std::string write_ros1_bag(const SimulatedSequence& seq, const std::string& compression, bool compressed_depth) {
  const std::string path = seq.tmp.file("posed_" + compression + (compressed_depth ? "_cd" : "") + ".bag");
  testing::Ros1PosedBagOptions o;
  o.compression = compression;
  o.compressed_depth = compressed_depth;
  testing::write_posed_ros1_bag(seq.ds, path, o);
  return path;
}

TEST(Ros1RoundTrip, Lz4Bag16UC1ReadsBackAndDetectsAsTheDataset) {
  const SimulatedSequence seq;
  const std::string bag = write_ros1_bag(seq, "lz4", false);
  testing::expect_same_frames(seq.ds, bag);
  testing::expect_same_detections(testing::detect_json(seq.tmp, seq.dataset_dir, "original"),
                                  testing::detect_json(seq.tmp, bag, "bag"));
}

TEST(Ros1RoundTrip, MapAndFuseGiveTheDatasetsResults) {
  const SimulatedSequence seq;
  const std::string bag = write_ros1_bag(seq, "lz4", false);
  const nlohmann::json mapped = testing::detect_json(seq.tmp, seq.dataset_dir, "map_original", "map");
  ASSERT_TRUE(mapped["frames"][0].contains("camera_to_world"));  // poses through /tf and /tf_static
  testing::expect_same_detections(mapped, testing::detect_json(seq.tmp, bag, "map_bag", "map"));
  testing::expect_same_detections(testing::detect_json(seq.tmp, seq.dataset_dir, "fuse_original", "fuse"),
                                  testing::detect_json(seq.tmp, bag, "fuse_bag", "fuse"));
}

TEST(Ros1RoundTrip, CompressedDepthAndBz2ReadBack) {
  const SimulatedSequence seq;
  testing::expect_same_frames(seq.ds, write_ros1_bag(seq, "bz2", true));
  testing::expect_same_frames(seq.ds, write_ros1_bag(seq, "none", false));
}

}  // namespace
}  // namespace tunnelmap
