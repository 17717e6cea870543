// The one writer of dataset.json: what it writes, the reader reads back as it was given.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/io/dataset.h"
#include "core/io/dataset_json_writer.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using nlohmann::json;

TEST(DatasetJsonWriter, FrameFilesSortInFrameOrder) {
  EXPECT_EQ(dataset_frame_file(0, ".png"), "000000.png");
  EXPECT_EQ(dataset_frame_file(42, ""), "000042");
  EXPECT_EQ(dataset_frame_file(1234567, ".png"), "1234567.png");
  EXPECT_LT(dataset_frame_file(9, ".png"), dataset_frame_file(10, ".png"));
}

TEST(DatasetJsonWriter, APoseKeepsItsBitsAndAnExactBottomRow) {
  Eigen::Isometry3d pose(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  pose.translation() = Eigen::Vector3d(1.25, -0.5, 12.0);
  pose.matrix()(3, 0) = 1e-17;  // what an arithmetic slip leaves in a stored matrix
  const json a = dataset_pose_json(pose);
  ASSERT_EQ(a.size(), 16u);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(a[4 * r + c].get<double>(), pose.matrix()(r, c));
  EXPECT_EQ(a[12].get<double>(), 0.0);
  EXPECT_EQ(a[15].get<double>(), 1.0);
}

TEST(DatasetJsonWriter, TheReaderReadsBackWhatWasWritten) {
  testing::IoTempDir tmp;
  std::filesystem::create_directories(tmp.path() / "depth");
  cv::imwrite(tmp.file("depth/" + dataset_frame_file(0, ".png")), cv::Mat(24, 32, CV_16UC1, cv::Scalar(1500)));
  Eigen::Isometry3d pose(Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()));
  pose.translation() = Eigen::Vector3d(3.0, 0.25, 1.5);
  const Eigen::Vector3d gravity = Eigen::Vector3d(0.1, 0.95, 0.2).normalized();
  json frames = json::array();
  frames.push_back({{"depth", "depth/" + dataset_frame_file(0, ".png")},
                    {"pose", dataset_pose_json(pose)},
                    {"gravity", dataset_vector_json(gravity)},
                    {"timestamp", 2.5}});
  const Intrinsics K{28.5, 28.6, 15.5, 11.5, 32, 24};
  json doc = dataset_document(K, 5000.0, Eigen::Vector3d(0, 0, 2), frames);
  doc["ground_truth"] = {{"width_m", 0.84}};
  write_dataset_json(tmp.path(), doc);

  const Dataset ds = read_dataset(tmp.path().string());
  EXPECT_EQ(ds.intrinsics.fx, 28.5);
  EXPECT_EQ(ds.intrinsics.height, 24);
  EXPECT_EQ(ds.depth_scale, 5000.0);
  EXPECT_TRUE(ds.up.isApprox(Eigen::Vector3d::UnitZ(), 1e-15));
  ASSERT_EQ(ds.frames.size(), 1u);
  ASSERT_TRUE(ds.frames[0].pose && ds.frames[0].gravity);
  EXPECT_TRUE(ds.frames[0].pose->matrix().isApprox(pose.matrix(), 1e-15));
  EXPECT_TRUE(ds.frames[0].gravity->isApprox(gravity, 1e-15));
  EXPECT_EQ(ds.frames[0].timestamp_s, 2.5);
  ASSERT_TRUE(ds.gt_width_m);
  EXPECT_EQ(*ds.gt_width_m, 0.84);
  EXPECT_NEAR(ds.load_frame(0).depth_m(3, 4), 0.3, 1e-6);  // 1500 units at 5000 per metre
}

}  // namespace
}  // namespace tunnelmap
