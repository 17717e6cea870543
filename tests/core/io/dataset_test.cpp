// Dataset folders (dataset.json + images): what loads, and the one-line error naming the file,
// frame and key for everything that does not.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "core/io/dataset.h"
#include "core/io/dataset_writer.h"
#include "core/io/frame_source.h"
#include "tests/core/io/io_fixtures.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::DatasetFixture;
using testing::IoTempDir;
using testing::expect_input_error;
using testing::kDsH;
using testing::kDsW;
using nlohmann::json;

TEST(Dataset, ValidDatasetLoads) {
  DatasetFixture ds;
  ds.write();
  const Dataset d = read_dataset(ds.tmp.path().string());
  EXPECT_EQ(d.json_path, ds.json_path());
  ASSERT_EQ(d.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(d.intrinsics.fx, 28.5);
  EXPECT_DOUBLE_EQ(d.intrinsics.fy, 28.6);
  EXPECT_EQ(d.intrinsics.width, 32);
  EXPECT_DOUBLE_EQ(d.depth_scale, 1000);
  EXPECT_TRUE(d.up.isApprox(Eigen::Vector3d::UnitZ()));  // normalised
  ASSERT_TRUE(d.gt_width_m && d.gt_height_m);
  EXPECT_DOUBLE_EQ(*d.gt_width_m, 0.82);
  EXPECT_DOUBLE_EQ(*d.gt_height_m, 1.30);
  EXPECT_EQ(d.ground_truth["material"], "steel");
  EXPECT_EQ(d.robot["links"][1], 0.25);
  EXPECT_EQ(d.raw["simulator"]["seed"], 4);
  EXPECT_EQ(d.frames[0].raw["distance_to_manhole_m"], 1.25);
  EXPECT_EQ(d.frames[0].joints, (std::vector<double>{0.1, -0.2, 0.3}));
  EXPECT_TRUE(d.frames[1].joints.empty());
  EXPECT_TRUE(d.frames[1].rgb_path.empty());

  const DepthFrame f0 = d.load_frame(0);
  EXPECT_EQ(f0.width, kDsW);
  EXPECT_FLOAT_EQ(f0.depth_m(5, 5), 1.2f);
  EXPECT_DOUBLE_EQ(f0.timestamp_s, 0.5);
  ASSERT_TRUE(f0.has_rgb());
  EXPECT_EQ(f0.rgb[0], 30);  // converted BGR -> RGB
  EXPECT_EQ(f0.rgb[1], 20);
  EXPECT_EQ(f0.rgb[2], 10);
  ASSERT_TRUE(f0.pose);
  EXPECT_TRUE(f0.pose->isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_DOUBLE_EQ(f0.intrinsics.cx, 15.5);

  const DepthFrame f1 = d.load_frame(1);
  EXPECT_FLOAT_EQ(f1.depth_m(0, 0), 1.3f);
  EXPECT_FALSE(f1.has_rgb());
  ASSERT_TRUE(f1.pose);
  // Row-major camera-to-world: camera x axis maps to world +Y, origin to (1, 2, 3).
  EXPECT_TRUE((*f1.pose * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d(1, 3, 3)));
  EXPECT_TRUE(f1.pose->translation().isApprox(Eigen::Vector3d(1, 2, 3)));

  const auto gt = d.load_gt_surfaces(0);
  ASSERT_EQ(gt.size(), std::size_t(kDsW * kDsH));
  EXPECT_EQ(gt[0], 3);
  EXPECT_EQ(gt[1], 7);
  EXPECT_TRUE(d.load_gt_surfaces(1).empty());
  expect_input_error([&] { d.load_frame(2); }, {"dataset.json", "out of range"});

  // The json file itself works as the argument, and "up" defaults to +Z.
  ds.j.erase("up");
  ds.j.erase("ground_truth");
  const Dataset d2 = read_dataset(ds.write());
  EXPECT_TRUE(d2.up.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_FALSE(d2.gt_width_m.has_value());
}

TEST(Dataset, JsonErrorsNameFileAndKey) {
  DatasetFixture ds;
  testing::write_text_file(ds.json_path(), "{ \"format\": \"tunnelmap-dataset/1\", ");
  expect_input_error([&] { read_dataset(ds.tmp.path().string()); }, {ds.json_path(), "malformed JSON"});
  testing::write_text_file(ds.json_path(), "[1, 2]");
  expect_input_error([&] { read_dataset(ds.tmp.path().string()); }, {ds.json_path(), "JSON object"});

  ds.expect_error([](json& j) { j["format"] = "tunnelmap-dataset/2"; }, {"'format'", "tunnelmap-dataset/2"});
  ds.expect_error([](json& j) { j.erase("format"); }, {"'format'", "missing"});
  ds.expect_error([](json& j) { j.erase("intrinsics"); }, {"'intrinsics'", "missing"});
  ds.expect_error([](json& j) { j["intrinsics"]["fx"] = "570"; }, {"'intrinsics.fx'", "number"});
  ds.expect_error([](json& j) { j["intrinsics"].erase("cy"); }, {"'intrinsics.cy'", "missing"});
  ds.expect_error([](json& j) { j["intrinsics"]["fx"] = 0; }, {"'intrinsics.fx'", "> 0"});
  ds.expect_error([](json& j) { j["intrinsics"]["fy"] = -3; }, {"'intrinsics.fy'", "> 0"});
  ds.expect_error([](json& j) { j["intrinsics"]["width"] = 0; }, {"'intrinsics.width'"});
  ds.expect_error([](json& j) { j["intrinsics"]["width"] = 9000; }, {"'intrinsics.width'", "8192"});
  ds.expect_error([](json& j) { j["intrinsics"]["height"] = 24.5; }, {"'intrinsics.height'", "integer"});
  ds.expect_error([](json& j) { j.erase("depth_scale"); }, {"'depth_scale'", "missing"});
  ds.expect_error([](json& j) { j["depth_scale"] = 0; }, {"'depth_scale'", "> 0"});
  ds.expect_error([](json& j) { j["up"] = json::array({0, 1}); }, {"'up'", "3 numbers"});
  ds.expect_error([](json& j) { j["up"] = json::array({0, 0, 0}); }, {"'up'", "zero"});
  ds.expect_error([](json& j) { j.erase("frames"); }, {"'frames'", "missing"});
  ds.expect_error([](json& j) { j["frames"] = json::array(); }, {"'frames'", "no frames"});
  ds.expect_error([](json& j) { j["frames"] = json::object(); }, {"'frames'", "array"});
  ds.expect_error([](json& j) { j["frames"][1] = 5; }, {"'frames[1]'", "object"});
  ds.expect_error([](json& j) { j["frames"][1].erase("depth"); }, {"'frames[1].depth'", "missing"});
  ds.expect_error([](json& j) { j["frames"][0]["timestamp"] = "noon"; }, {"'frames[0].timestamp'", "number"});
  ds.expect_error([](json& j) { j["frames"][0]["joints"] = json::array({1, "x"}); }, {"'frames[0].joints[1]'", "number"});
  ds.expect_error([](json& j) { j["ground_truth"]["width_m"] = "wide"; }, {"'ground_truth.width_m'", "number"});
}

TEST(Dataset, PoseErrorsNameFrameAndKey) {
  DatasetFixture ds;
  ds.expect_error([](json& j) { j["frames"][1]["pose"].erase(15); }, {"'frames[1].pose'", "16 numbers", "got 15"});
  ds.expect_error([](json& j) { j["frames"][1]["pose"][3] = "1"; }, {"'frames[1].pose[3]'", "number"});
  ds.expect_error([](json& j) { j["frames"][0]["pose"] = 7; }, {"'frames[0].pose'", "array"});
  ds.expect_error([](json& j) { j["frames"][1]["pose"][14] = 0.5; }, {"'frames[1].pose'", "bottom row"});
  ds.expect_error([](json& j) { j["frames"][1]["pose"][0] = 0.01; }, {"'frames[1].pose'", "orthonormal"});
  ds.expect_error([](json& j) { j["frames"][0]["pose"][0] = 1.01; }, {"'frames[0].pose'", "orthonormal"});
  ds.expect_error([](json& j) { j["frames"][0]["pose"][10] = -1; }, {"'frames[0].pose'", "reflection"});
  // Within the 1e-3 tolerance is accepted.
  ds.j["frames"][0]["pose"][0] = 1.0004;
  EXPECT_EQ(read_dataset(ds.write()).frames.size(), 2u);
}

TEST(Dataset, AFramesGravityIsReadAsAUnitDirectionAndABadOneNamesItsKey) {
  DatasetFixture ds;
  ds.j["frames"][0]["gravity"] = json::array({0.0, 9.81, 0.0});  // the camera's y points down
  const Dataset d = read_dataset(ds.write());
  ASSERT_TRUE(d.frames[0].gravity);
  EXPECT_TRUE(d.frames[0].gravity->isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_FALSE(d.frames[1].gravity);
  const DepthFrame f0 = d.load_frame(0);
  ASSERT_TRUE(f0.gravity);
  EXPECT_TRUE(f0.gravity->isApprox(Eigen::Vector3d::UnitY()));
  ds.expect_error([](json& j) { j["frames"][0]["gravity"] = json::array({0.0, 1.0}); }, {"'frames[0].gravity'", "3 numbers", "got 2"});
  ds.expect_error([](json& j) { j["frames"][1]["gravity"] = json::array({0.0, 0.0, 0.0}); }, {"'frames[1].gravity'", "non-zero"});
  ds.expect_error([](json& j) { j["frames"][1]["gravity"] = json::array({0.0, "down", 0.0}); }, {"'frames[1].gravity[1]'", "number"});
  // A copy of the dataset keeps it.
  IoTempDir out;
  write_dataset_folder(d, out.file("copy"), SequenceExport{});
  const Dataset copy = read_dataset(out.file("copy"));
  ASSERT_TRUE(copy.frames[0].gravity);
  EXPECT_TRUE(copy.frames[0].gravity->isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_FALSE(copy.frames[1].gravity);
}

TEST(Dataset, PathErrorsNameFrameAndKey) {
  DatasetFixture ds;
  ds.expect_error([](json& j) { j["frames"][1]["depth"] = "depth/000009.png"; }, {"'frames[1].depth'", "not found"});
  ds.expect_error([](json& j) { j["frames"][0]["rgb"] = "rgb/missing.png"; }, {"'frames[0].rgb'", "not found"});
  ds.expect_error([](json& j) { j["frames"][0]["depth"] = 3; }, {"'frames[0].depth'", "string"});
  ds.expect_error([](json& j) { j["frames"][0]["depth"] = "/etc/passwd"; }, {"'frames[0].depth'", "relative"});
  ds.expect_error([](json& j) { j["frames"][0]["depth"] = "depth"; }, {"'frames[0].depth'", "not a regular file"});

  // `..` that leaves the folder, even towards a file that exists.
  IoTempDir outside;
  cv::imwrite(outside.file("x.png"), cv::Mat(kDsH, kDsW, CV_16UC1, cv::Scalar(1)));
  const std::string escape = "../" + outside.path().filename().string() + "/x.png";
  ds.expect_error([&](json& j) { j["frames"][0]["depth"] = escape; }, {"'frames[0].depth'", "escapes the dataset folder"});
  ds.expect_error([](json& j) { j["frames"][1]["gt_surfaces"] = "gt/../../gt/000000.png"; },
                  {"'frames[1].gt_surfaces'", "escapes"});
  // `..` that stays inside is fine.
  ds.j["frames"][1]["depth"] = "rgb/../depth/000001.png";
  EXPECT_EQ(read_dataset(ds.write()).frames.size(), 2u);

  // A symlink inside the folder that points outside it.
  fs::create_directory_symlink(outside.path(), ds.tmp.path() / "link");
  ds.expect_error([](json& j) { j["frames"][0]["depth"] = "link/x.png"; }, {"'frames[0].depth'", "escapes"});
}

TEST(Dataset, ImageErrorsNameFrameAndKey) {
  DatasetFixture ds;
  cv::imwrite(ds.tmp.file("depth/small.png"), cv::Mat(10, 12, CV_16UC1, cv::Scalar(1)));
  cv::imwrite(ds.tmp.file("rgb/grey.png"), cv::Mat(kDsH, kDsW, CV_8UC1, cv::Scalar(1)));
  cv::imwrite(ds.tmp.file("rgb/small.png"), cv::Mat(10, 12, CV_8UC3, cv::Scalar(1)));
  cv::imwrite(ds.tmp.file("depth/eight.png"), cv::Mat(kDsH, kDsW, CV_8UC1, cv::Scalar(1)));
  cv::imwrite(ds.tmp.file("gt/small.png"), cv::Mat(10, 12, CV_16UC1, cv::Scalar(1)));

  const auto load_error = [&](const std::string& key, const std::string& file,
                              const std::vector<std::string>& extra) {
    json saved = ds.j;
    ds.j["frames"][1][key] = file;
    const Dataset d = read_dataset(ds.write());
    std::vector<std::string> parts = {ds.json_path(), "'frames[1]." + key + "'"};
    parts.insert(parts.end(), extra.begin(), extra.end());
    expect_input_error([&] { key == "gt_surfaces" ? (void)d.load_gt_surfaces(1) : (void)d.load_frame(1); }, parts);
    ds.j = saved;
  };
  load_error("depth", "depth/small.png", {"12x10", "32x24"});
  load_error("depth", "depth/eight.png", {"8-bit"});
  load_error("rgb", "rgb/grey.png", {"8-bit 3-channel"});
  load_error("rgb", "rgb/small.png", {"12x10"});
  load_error("gt_surfaces", "gt/small.png", {"12x10"});
}

TEST(Dataset, MissingFolderOrJson) {
  IoTempDir tmp;
  expect_input_error([&] { read_dataset(tmp.file("nope")); }, {"nope", "not found"});
  expect_input_error([&] { read_dataset(tmp.path().string()); }, {"no dataset.json"});
}

TEST(Dataset, SymlinkLoopsAreRefusedWithTheirReason) {
  DatasetFixture ds;
  fs::create_symlink("loop", ds.tmp.path() / "loop");
  ds.expect_error([](json& j) { j["frames"][0]["depth"] = "loop/000000.png"; }, {"'frames[0].depth'", "symbolic links"});
  ds.expect_error([](json& j) { j["frames"][0]["rgb"] = "loop"; }, {"'frames[0].rgb'", "symbolic links"});
  // The dataset folder itself is a loop.
  const std::string looped = (ds.tmp.path() / "loop").string();
  expect_input_error([&] { read_dataset(looped); }, {looped, "symbolic links"});
  expect_input_error([&] { open_input(looped, {}); }, {looped, "symbolic links"});
}

TEST(Dataset, NonFiniteAndNonNumericValuesNameTheKey) {
  DatasetFixture ds;
  // JSON has no NaN; an overflowing literal is refused by the parser itself.
  ds.j["depth_scale"] = 1000;
  std::string text = ds.j.dump();
  const auto at = text.find("\"depth_scale\":1000");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 18, "\"depth_scale\":1e999");
  testing::write_text_file(ds.json_path(), text);
  expect_input_error([&] { read_dataset(ds.tmp.path().string()); }, {ds.json_path(), "malformed JSON", "number overflow", "1e999"});
  ds.expect_error([](json& j) { j["frames"][0]["pose"] = json::array({"a", 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}); },
                  {"'frames[0].pose[0]'", "number"});
  ds.expect_error([](json& j) { j["intrinsics"] = "kinect"; }, {"'intrinsics'", "object"});
  ds.expect_error([](json& j) { j["format"] = 1; }, {"'format'", "string"});
}

}  // namespace
}  // namespace tunnelmap
