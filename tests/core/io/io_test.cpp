// Input readers: depth PNG, organised PCD, dataset folders, the input dispatcher, the PLY mesh
// reader (round trips with our exporters, hostile files), real frames.
#include <gtest/gtest.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/export/map_ply.h"
#include "core/export/mesh_ply.h"
#include "core/export/planes_ply.h"
#include "core/io/json_file.h"
#include "core/io/ply_mesh_reader.h"
#include "core/io/readers.h"
#include "core/util/error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::IoTempDir;
using testing::expect_input_error;
using nlohmann::json;


cv::Mat depth_ramp(int w, int h) {
  cv::Mat img(h, w, CV_16UC1);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) img.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(500 + 37 * v + u);
  img.at<std::uint16_t>(0, 0) = 0;       // no measurement
  img.at<std::uint16_t>(1, 1) = 65535;   // largest value survives
  return img;
}

// ---------------------------------------------------------------- depth PNG

TEST(DepthPng, RoundTripKeepsValuesAndScalesDefaultIntrinsics) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  const cv::Mat img = depth_ramp(320, 240);
  ASSERT_TRUE(cv::imwrite(path, img));

  const DepthFrame f = read_depth_png(path, ReadOptions{});
  ASSERT_EQ(f.width, 320);
  ASSERT_EQ(f.height, 240);
  EXPECT_EQ(f.source, path);
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 1000.0);
  EXPECT_FALSE(f.has_rgb());
  EXPECT_FALSE(f.pose.has_value());
  for (int v = 0; v < 240; v += 7)
    for (int u = 0; u < 320; u += 5)
      ASSERT_EQ(f.depth[v * 320 + u], static_cast<float>(img.at<std::uint16_t>(v, u)));
  EXPECT_EQ(f.depth[0], 0.f);
  EXPECT_EQ(f.depth[321], 65535.f);
  EXPECT_FLOAT_EQ(f.depth_m(10, 2), (500 + 37 * 2 + 10) / 1000.f);
  // PrimeSense VGA scaled to half size.
  EXPECT_NEAR(f.intrinsics.fx, 285.15, 1e-9);
  EXPECT_NEAR(f.intrinsics.fy, 285.15, 1e-9);
  EXPECT_NEAR(f.intrinsics.cx, 159.5, 1e-9);
  EXPECT_NEAR(f.intrinsics.cy, 119.5, 1e-9);
  EXPECT_EQ(f.intrinsics.width, 320);
  EXPECT_EQ(f.intrinsics.height, 240);
}

TEST(DepthPng, UsesGivenScaleAndIntrinsicsWithImageSize) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  ASSERT_TRUE(cv::imwrite(path, depth_ramp(64, 48)));
  ReadOptions opt;
  opt.depth_units_per_m = 5000;
  opt.intrinsics = Intrinsics{525, 526, 31, 23, 640, 480};
  const DepthFrame f = read_depth_png(path, opt);
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 5000);
  EXPECT_DOUBLE_EQ(f.intrinsics.fx, 525);
  EXPECT_DOUBLE_EQ(f.intrinsics.fy, 526);
  EXPECT_DOUBLE_EQ(f.intrinsics.cx, 31);
  EXPECT_EQ(f.intrinsics.width, 64);   // from the image, not the option
  EXPECT_EQ(f.intrinsics.height, 48);
  EXPECT_FLOAT_EQ(f.depth_m(3, 2), (500 + 74 + 3) / 5000.f);
}

TEST(DepthPng, Rejects8BitAndColourImages) {
  IoTempDir tmp;
  const std::string grey8 = tmp.file("grey8.png"), bgr8 = tmp.file("bgr8.png"),
                    bgr16 = tmp.file("bgr16.png");
  ASSERT_TRUE(cv::imwrite(grey8, cv::Mat(20, 30, CV_8UC1, cv::Scalar(100))));
  ASSERT_TRUE(cv::imwrite(bgr8, cv::Mat(20, 30, CV_8UC3, cv::Scalar(1, 2, 3))));
  ASSERT_TRUE(cv::imwrite(bgr16, cv::Mat(20, 30, CV_16UC3, cv::Scalar(1000, 2000, 3000))));
  expect_input_error([&] { read_depth_png(grey8, {}); }, {grey8, "is an 8-bit grey image; depth PNGs must be 16-bit single channel"});
  expect_input_error([&] { read_depth_png(bgr8, {}); }, {bgr8, "8-bit", "16-bit single channel"});
  expect_input_error([&] { read_depth_png(bgr16, {}); }, {bgr16, "RGB", "16-bit single channel"});
}

TEST(DepthPng, RejectsTruncatedFile) {
  IoTempDir tmp;
  const std::string good = tmp.file("good.png");
  cv::Mat img(240, 320, CV_16UC1);
  cv::randu(img, 0, 8000);  // incompressible, so cutting loses image rows
  ASSERT_TRUE(cv::imwrite(good, img));
  const auto bytes = testing::read_binary_file(good);
  ASSERT_GT(bytes.size(), 1000u);

  const std::string half = tmp.file("half.png");
  testing::write_binary_file(half, std::vector<char>(bytes.begin(), bytes.begin() + bytes.size() / 2));
  expect_input_error([&] { read_depth_png(half, {}); }, {half, "truncated"});

  // Only the IEND chunk missing: the pixels are all there but the file is still cut short.
  const std::string no_end = tmp.file("no_end.png");
  testing::write_binary_file(no_end, std::vector<char>(bytes.begin(), bytes.end() - 12));
  expect_input_error([&] { read_depth_png(no_end, {}); }, {no_end, "truncated"});

  // Header only.
  const std::string header_only = tmp.file("header_only.png");
  testing::write_binary_file(header_only, std::vector<char>(bytes.begin(), bytes.begin() + 40));
  expect_input_error([&] { read_depth_png(header_only, {}); }, {header_only});
}

TEST(DepthPng, RejectsTextFileRenamedPng) {
  IoTempDir tmp;
  const std::string path = tmp.file("notes.png");
  testing::write_text_file(path, "this is not an image, just some text\nsecond line\n");
  expect_input_error([&] { read_depth_png(path, {}); }, {path, "is not a PNG"});
  const std::string empty = tmp.file("empty.png");
  testing::write_text_file(empty, "");
  expect_input_error([&] { read_depth_png(empty, {}); }, {empty, "is not a PNG"});
}

// A PNG signature and IHDR claiming the given size, and nothing else.
std::vector<char> png_header_bytes(std::uint32_t w, std::uint32_t h) {
  std::vector<char> b = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
  for (std::uint32_t x : {w, h})
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<char>((x >> s) & 0xff));
  for (char c : {16, 0, 0, 0, 0}) b.push_back(c);  // 16-bit grey
  for (int i = 0; i < 4; ++i) b.push_back(0);       // CRC (not checked before the size test)
  return b;
}

TEST(DepthPng, RejectsAbsurdHeaderDimensionsBeforeDecoding) {
  IoTempDir tmp;
  const std::string huge = tmp.file("huge.png"), wide = tmp.file("wide.png"), zero = tmp.file("zero.png");
  testing::write_binary_file(huge, png_header_bytes(2000000000u, 2000000000u));
  testing::write_binary_file(wide, png_header_bytes(8193, 10));
  testing::write_binary_file(zero, png_header_bytes(0, 480));
  // "absurd image size" comes from the header check: the decoder never ran.
  expect_input_error([&] { read_depth_png(huge, {}); }, {huge, "absurd image size 2000000000x2000000000"});
  expect_input_error([&] { read_depth_png(wide, {}); }, {wide, "absurd image size 8193x10"});
  expect_input_error([&] { read_depth_png(zero, {}); }, {zero, "absurd image size 0x480"});
}

TEST(DepthPng, MissingFileAndFolder) {
  IoTempDir tmp;
  const std::string missing = tmp.file("nope.png");
  expect_input_error([&] { read_depth_png(missing, {}); }, {missing, "not found"});
  expect_input_error([&] { read_depth_png(tmp.path().string(), {}); }, {"is a folder"});
}

// ---------------------------------------------------------------- organised PCD

const Intrinsics kPcdTruth{301.5, 298.25, 39.3, 29.8, 80, 60};

// A tilted plane seen by a camera with kPcdTruth, with a rectangular hole of NaNs.
pcl::PointCloud<pcl::PointXYZ> organised_plane_cloud() {
  pcl::PointCloud<pcl::PointXYZ> cloud(80, 60);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < 60; ++v)
    for (int u = 0; u < 80; ++u) {
      auto& p = cloud.at(u, v);
      if (u >= 10 && u < 20 && v >= 5 && v < 15) {
        p.x = p.y = p.z = nan;
        continue;
      }
      const float z = 1.5f + 0.01f * u + 0.004f * v;
      p.x = static_cast<float>((u - kPcdTruth.cx) * z / kPcdTruth.fx);
      p.y = static_cast<float>((v - kPcdTruth.cy) * z / kPcdTruth.fy);
      p.z = z;
    }
  cloud.is_dense = false;
  return cloud;
}

TEST(OrganizedPcd, RoundTripDepthAndEstimatedIntrinsics) {
  IoTempDir tmp;
  const std::string path = tmp.file("cloud.pcd");
  const auto cloud = organised_plane_cloud();
  ASSERT_EQ(pcl::io::savePCDFile(path, cloud, true), 0);

  const DepthFrame f = read_organized_pcd(path, ReadOptions{});
  ASSERT_EQ(f.width, 80);
  ASSERT_EQ(f.height, 60);
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 1.0);
  EXPECT_EQ(f.depth[5 * 80 + 10], 0.f);  // NaN -> 0
  EXPECT_FLOAT_EQ(f.depth[30 * 80 + 50], cloud.at(50, 30).z);
  EXPECT_FLOAT_EQ(f.depth_m(79, 59), 1.5f + 0.79f + 0.236f);
  EXPECT_NEAR(f.intrinsics.fx, kPcdTruth.fx, 0.1);
  EXPECT_NEAR(f.intrinsics.fy, kPcdTruth.fy, 0.1);
  EXPECT_NEAR(f.intrinsics.cx, kPcdTruth.cx, 0.1);
  EXPECT_NEAR(f.intrinsics.cy, kPcdTruth.cy, 0.1);
  EXPECT_EQ(f.intrinsics.width, 80);
  EXPECT_EQ(f.intrinsics.height, 60);
  std::printf("estimated fx %.4f fy %.4f cx %.4f cy %.4f (truth 301.5 298.25 39.3 29.8)\n",
              f.intrinsics.fx, f.intrinsics.fy, f.intrinsics.cx, f.intrinsics.cy);

  // Given intrinsics win over the estimate.
  ReadOptions opt;
  opt.intrinsics = Intrinsics{100, 100, 40, 30, 1, 1};
  const DepthFrame g = read_organized_pcd(path, opt);
  EXPECT_DOUBLE_EQ(g.intrinsics.fx, 100);
  EXPECT_EQ(g.intrinsics.width, 80);
}

TEST(OrganizedPcd, ReadsAsciiPcdToo) {
  IoTempDir tmp;
  const std::string path = tmp.file("ascii.pcd");
  ASSERT_EQ(pcl::io::savePCDFileASCII(path, organised_plane_cloud()), 0);
  const DepthFrame f = read_organized_pcd(path, ReadOptions{});
  EXPECT_NEAR(f.intrinsics.fx, kPcdTruth.fx, 0.1);
  EXPECT_NEAR(f.intrinsics.cy, kPcdTruth.cy, 0.1);
}

TEST(OrganizedPcd, RejectsUnorganisedCloud) {
  IoTempDir tmp;
  const std::string path = tmp.file("flat.pcd");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 500; ++i) cloud.push_back(pcl::PointXYZ(0.01f * i, 0.f, 1.f));
  ASSERT_EQ(cloud.height, 1u);
  ASSERT_EQ(pcl::io::savePCDFile(path, cloud, true), 0);
  expect_input_error([&] { read_organized_pcd(path, {}); }, {path, "is not organised"});
}

TEST(OrganizedPcd, TooFewValidPointsAsksForIntrinsics) {
  IoTempDir tmp;
  const std::string path = tmp.file("sparse.pcd");
  auto cloud = organised_plane_cloud();
  for (std::size_t i = 50; i < cloud.size(); ++i) cloud[i].z = std::numeric_limits<float>::quiet_NaN();
  ASSERT_EQ(pcl::io::savePCDFile(path, cloud, true), 0);
  expect_input_error([&] { read_organized_pcd(path, {}); }, {path, "--intrinsics"});
  ReadOptions opt;
  opt.intrinsics = kPcdTruth;
  EXPECT_EQ(read_organized_pcd(path, opt).width, 80);  // fine when they are given
}

TEST(OrganizedPcd, RejectsGarbageMissingAndAbsurdHeader) {
  IoTempDir tmp;
  const std::string garbage = tmp.file("garbage.pcd"), missing = tmp.file("missing.pcd"),
                    huge = tmp.file("huge.pcd");
  testing::write_text_file(garbage, "hello, I am not a point cloud\n");
  testing::write_text_file(huge,
                           "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                           "WIDTH 20000\nHEIGHT 20000\nVIEWPOINT 0 0 0 1 0 0 0\n"
                           "POINTS 400000000\nDATA binary\n");
  expect_input_error([&] { read_organized_pcd(garbage, {}); }, {garbage});
  expect_input_error([&] { read_organized_pcd(missing, {}); }, {missing, "not found"});
  // PCL's own readHeader would allocate WIDTH x HEIGHT points (4.8 GB here) before failing.
  expect_input_error([&] { read_organized_pcd(huge, {}); }, {huge, "absurd cloud size 20000x20000"});
}

TEST(OrganizedPcd, RejectsTruncatedAndInconsistentFiles) {
  IoTempDir tmp;
  const std::string good = tmp.file("good.pcd"), cut = tmp.file("cut.pcd"), odd = tmp.file("odd.pcd");
  ASSERT_EQ(pcl::io::savePCDFile(good, organised_plane_cloud(), true), 0);
  const auto bytes = testing::read_binary_file(good);
  testing::write_binary_file(cut, std::vector<char>(bytes.begin(), bytes.end() - 1000));
  expect_input_error([&] { read_organized_pcd(cut, {}); }, {cut, "truncated PCD"});
  testing::write_text_file(odd,
                           "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                           "WIDTH 4\nHEIGHT 3\nPOINTS 13\nDATA ascii\n");
  expect_input_error([&] { read_organized_pcd(odd, {}); }, {odd, "POINTS 13"});
}

// ---------------------------------------------------------------- dataset folders

constexpr int kDsW = 32, kDsH = 24;

// A valid 2-frame dataset: depth, rgb and ground-truth images, poses, joints, up, ground truth.
struct DatasetFixture {
  IoTempDir tmp;
  json j;

  DatasetFixture() {
    fs::create_directories(tmp.path() / "depth");
    fs::create_directories(tmp.path() / "rgb");
    fs::create_directories(tmp.path() / "gt");
    for (int i = 0; i < 2; ++i) {
      const std::string n = "00000" + std::to_string(i) + ".png";
      cv::Mat d(kDsH, kDsW, CV_16UC1, cv::Scalar(1200 + 100 * i));
      cv::Mat rgb(kDsH, kDsW, CV_8UC3, cv::Scalar(10, 20, 30));  // B G R
      cv::Mat gt(kDsH, kDsW, CV_16UC1, cv::Scalar(3));
      gt.at<std::uint16_t>(0, 1) = 7;
      cv::imwrite(tmp.file("depth/" + n), d);
      cv::imwrite(tmp.file("rgb/" + n), rgb);
      cv::imwrite(tmp.file("gt/" + n), gt);
    }
    // Frame 1: camera rotated 90 degrees about world Z, at (1, 2, 3).
    j = json::parse(R"({
      "format": "tunnelmap-dataset/1",
      "simulator": {"seed": 4},
      "intrinsics": {"fx": 28.5, "fy": 28.6, "cx": 15.5, "cy": 11.5, "width": 32, "height": 24},
      "depth_scale": 1000,
      "up": [0, 0, 2],
      "frames": [
        {"depth": "depth/000000.png", "rgb": "rgb/000000.png", "gt_surfaces": "gt/000000.png",
         "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1], "joints": [0.1, -0.2, 0.3], "timestamp": 0.5,
         "pose_group": 2, "distance_to_manhole_m": 1.25},
        {"depth": "depth/000001.png",
         "pose": [0,-1,0,1, 1,0,0,2, 0,0,1,3, 0,0,0,1], "timestamp": 1.0}
      ],
      "robot": {"links": [0.3, 0.25]},
      "ground_truth": {"width_m": 0.82, "height_m": 1.30, "material": "steel"}
    })");
  }
  std::string json_path() const { return tmp.file("dataset.json"); }
  std::string write() const {
    testing::write_text_file(json_path(), j.dump(2));
    return json_path();
  }
  // Writes `j` after `edit` and expects read_dataset to fail naming dataset.json and `parts`.
  void expect_error(const std::function<void(json&)>& edit, std::vector<std::string> parts) {
    json saved = j;
    edit(j);
    write();
    parts.insert(parts.begin(), json_path());
    expect_input_error([&] { read_dataset(tmp.path().string()); }, parts);
    j = saved;
  }
};

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

// ---------------------------------------------------------------- open_input

TEST(OpenInput, DispatchesByTypeAndRejectsUnknown) {
  DatasetFixture ds;
  ds.write();
  const std::string png = ds.tmp.file("depth/000000.png");
  const auto a = open_input(png, {});
  EXPECT_EQ(a->size(), 1u);
  EXPECT_EQ(a->dataset(), nullptr);
  EXPECT_EQ(a->load(0).width, kDsW);
  EXPECT_EQ(a->describe(0), png);
  expect_input_error([&] { a->load(1); }, {"out of range"});

  const std::string pcd = ds.tmp.file("cloud.pcd");
  ASSERT_EQ(pcl::io::savePCDFile(pcd, organised_plane_cloud(), true), 0);
  EXPECT_EQ(open_input(pcd, {})->load(0).depth_units_per_m, 1.0);

  for (const std::string& in : {ds.tmp.path().string(), ds.json_path()}) {
    const auto s = open_input(in, {});
    ASSERT_EQ(s->size(), 2u);
    ASSERT_NE(s->dataset(), nullptr);
    EXPECT_EQ(s->describe(1), "frame 1/2 (depth/000001.png)");
    EXPECT_TRUE(s->load(1).pose.has_value());
  }

  // Content sniffing when the extension says nothing.
  const std::string no_ext = ds.tmp.file("frame_without_extension");
  fs::copy_file(png, no_ext);
  EXPECT_EQ(open_input(no_ext, {})->load(0).width, kDsW);

  const std::string txt = ds.tmp.file("readme.txt");
  testing::write_text_file(txt, "hello");
  expect_input_error([&] { open_input(txt, {}); }, {txt, "unknown input type"});
  expect_input_error([&] { open_input(ds.tmp.file("missing.png"), {}); }, {"missing.png", "not found"});
  expect_input_error([&] { open_input(ds.tmp.file("depth"), {}); }, {"no dataset.json"});
}

// ---------------------------------------------------------------- hardening: PNG / PCD / dataset

TEST(DepthPng, AllZeroDepthReadsAsFrameWithNoValidPixel) {
  // Decision (docs/robustness.md): a blank frame is data, not an error; the pipeline reports
  // "no tunnel" for it, so one blinded frame does not abort a whole sequence.
  IoTempDir tmp;
  const std::string path = tmp.file("zero.png");
  ASSERT_TRUE(cv::imwrite(path, cv::Mat(24, 32, CV_16UC1, cv::Scalar(0))));
  const DepthFrame f = read_depth_png(path, {});
  ASSERT_EQ(f.depth.size(), 32u * 24u);
  for (float d : f.depth) EXPECT_EQ(d, 0.f);
}

TEST(RgbImage, AcceptsPngAndJpegOnly) {
  IoTempDir tmp;
  const cv::Mat bgr(6, 8, CV_8UC3, cv::Scalar(30, 20, 200));
  for (const char* name : {"c.png", "c.jpg", "c.bmp"}) ASSERT_TRUE(cv::imwrite(tmp.file(name), bgr));
  int w = 0, h = 0;
  for (const char* name : {"c.png", "c.jpg"}) {
    const auto rgb = read_rgb_image(tmp.file(name), w, h);
    ASSERT_EQ(rgb.size(), 8u * 6u * 3u);
    EXPECT_NEAR(rgb[0], 200, 3) << name;  // red first
    EXPECT_NEAR(rgb[2], 30, 3) << name;
  }
  // OpenCV would decode BMP, TIFF, EXR...: only the formats datasets use are let through.
  expect_input_error([&] { read_rgb_image(tmp.file("c.bmp"), w, h); }, {"c.bmp", "neither a PNG nor a JPEG"});
  // A JPEG whose frame header claims 60000x50000 is refused before decoding.
  auto jpeg = testing::read_binary_file(tmp.file("c.jpg"));
  for (std::size_t i = 2; i + 9 < jpeg.size(); ++i)
    if (std::uint8_t(jpeg[i]) == 0xff && std::uint8_t(jpeg[i + 1]) == 0xc0) {
      jpeg[i + 5] = char(50000 >> 8), jpeg[i + 6] = char(50000 & 0xff);
      jpeg[i + 7] = char(60000 >> 8), jpeg[i + 8] = char(60000 & 0xff);
      break;
    }
  testing::write_binary_file(tmp.file("huge.jpg"), jpeg);
  expect_input_error([&] { read_rgb_image(tmp.file("huge.jpg"), w, h); }, {"huge.jpg", "absurd image size 60000x50000"});
}

TEST(DepthPng, DecodesFromMemoryLikeFromFile) {
  IoTempDir tmp;
  const std::string path = tmp.file("d.png");
  ASSERT_TRUE(cv::imwrite(path, depth_ramp(20, 10)));
  const auto raw = testing::read_binary_file(path);
  const std::vector<std::uint8_t> bytes(raw.begin(), raw.end());
  const DepthFrame a = read_depth_png(path, {}), b = decode_depth_png(bytes, "mem.png", {});
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(b.source, "mem.png");
  // Every truncation of a valid PNG is refused (or, if the cut is after IEND, read intact).
  for (std::size_t n = 0; n + 12 < bytes.size(); ++n)
    expect_input_error([&] { decode_depth_png({bytes.begin(), bytes.begin() + n}, "cut.png", {}); }, {"cut.png"});
}

std::string pcd_text(const std::string& fields_size_type_count, const std::string& data,
                     const std::string& body, int w = 4, int h = 3) {
  return "VERSION .7\n" + fields_size_type_count + "WIDTH " + std::to_string(w) + "\nHEIGHT " +
         std::to_string(h) + "\nPOINTS " + std::to_string(w * h) + "\nDATA " + data + "\n" + body;
}

TEST(OrganizedPcd, RejectsInconsistentFieldDescriptions) {
  IoTempDir tmp;
  const std::string xyz = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  std::string ascii_body;
  for (int i = 0; i < 12; ++i) ascii_body += "0.1 0.2 1.5\n";
  const auto expect = [&](const std::string& name, const std::string& text, const std::vector<std::string>& parts) {
    const std::string path = tmp.file(name);
    testing::write_text_file(path, text);
    std::vector<std::string> all = {path};
    all.insert(all.end(), parts.begin(), parts.end());
    expect_input_error([&] { read_organized_pcd(path, {}); }, all);
  };
  expect("size_count.pcd", pcd_text("FIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"one entry per field"});
  expect("bad_type.pcd", pcd_text("FIELDS x y z\nSIZE 4 4 4\nTYPE F Q F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"bad TYPE 'Q'"});
  expect("bad_size.pcd", pcd_text("FIELDS x y z\nSIZE 4 3 4\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"bad SIZE 3 for field 'y'"});
  expect("float16.pcd", pcd_text("FIELDS x y z\nSIZE 4 2 4\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"TYPE F with SIZE 2"});
  expect("double_xyz.pcd", pcd_text("FIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"field 'x' must be a single 32-bit float"});
  expect("zero_count.pcd", pcd_text("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 0 1\n", "ascii", ascii_body),
         {"bad COUNT value '0'"});
  // binary_compressed: the sizes of the LZF block must agree with the header and the file.
  const auto compressed = [&](std::uint32_t comp, std::uint32_t raw, std::size_t payload) {
    std::string sizes(8, '\0');
    for (int k = 0; k < 4; ++k) {
      sizes[k] = static_cast<char>((comp >> (8 * k)) & 0xff);
      sizes[4 + k] = static_cast<char>((raw >> (8 * k)) & 0xff);
    }
    return pcd_text(xyz, "binary_compressed", sizes + std::string(payload, '\x1f'));
  };
  expect("lzf_raw.pcd", compressed(20, 1000, 20), {"compressed block holds 1000 bytes", "needs 144"});
  expect("lzf_past_end.pcd", compressed(5000, 144, 20), {"runs past the end"});
  // Lines PCL reads differently from us (its header ends at a blank line; it reads on after
  // DATA): found by fuzzing, a leading "\r\n" line made PCL dereference null.
  expect("leading_cr.pcd", "\r\n" + pcd_text(xyz, "ascii", ascii_body), {"blank, indented or binary line"});
  expect("indented.pcd", pcd_text(" FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", ascii_body),
         {"blank, indented or binary line"});
  expect("keyword_after_data.pcd", pcd_text(xyz, "ascii", "\n# c\nWIDTH 400\n" + ascii_body),
         {"data after DATA starts with a header line ('WIDTH')"});
  // PCL acts on each header line in order (every POINTS line allocates): found by fuzzing, a
  // first "POINTS 1500000000000008" made PCL request 18 PB before the second POINTS line.
  expect("points_twice.pcd",
         "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 4\nHEIGHT 3\nPOINTS 1500000000000008\nPOINTS 12\nDATA ascii\n" +
             ascii_body,
         {"POINTS appears more than once"});
  expect("fields_twice.pcd", pcd_text("FIELDS x y z\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n", "ascii", ascii_body),
         {"FIELDS appears more than once"});
  expect("count_first.pcd", pcd_text("FIELDS x y z\nCOUNT 1 1 1\nSIZE 4 4 4\nTYPE F F F\n", "ascii", ascii_body),
         {"COUNT before TYPE"});
  expect("points_first.pcd",
         "FIELDS x y z\nWIDTH 4\nHEIGHT 3\nPOINTS 12\nSIZE 4 4 4\nTYPE F F F\nDATA ascii\n" + ascii_body,
         {"POINTS before TYPE"});
  // A header line longer than 64 KiB (no newline): refused without reading the file whole.
  expect("no_newline.pcd", "VERSION .7\nFIELDS " + std::string(70000, 'x'), {"incomplete header"});
}

TEST(OrganizedPcd, NanAndInfinitePointsBecomeNoMeasurement) {
  // Decision: NaN / inf points are "no measurement" (depth 0). With no valid point left the
  // intrinsics cannot be estimated: a clear error asking for --intrinsics; with them, a blank frame.
  IoTempDir tmp;
  const std::string path = tmp.file("nan.pcd");
  std::string body;
  for (int i = 0; i < 12; ++i) body += i % 2 ? "nan nan nan\n" : "inf 1 inf\n";
  testing::write_text_file(path, pcd_text("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n", "ascii", body));
  expect_input_error([&] { read_organized_pcd(path, {}); }, {path, "--intrinsics"});
  ReadOptions opt;
  opt.intrinsics = Intrinsics{5, 5, 1.5, 1, 4, 3};
  const DepthFrame f = read_organized_pcd(path, opt);
  ASSERT_EQ(f.depth.size(), 12u);
  for (float d : f.depth) EXPECT_EQ(d, 0.f);
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

TEST(JsonFile, EveryJsonProblemIsOneInputErrorLine) {
  // Found by fuzzing the presets: nlohmann throws out_of_range, not parse_error, for "1e999".
  IoTempDir tmp;
  testing::write_text_file(tmp.file("overflow.json"), "{\"params\": {\"grow.angle_deg\": 1e999}}");
  expect_input_error([&] { read_json_file(tmp.file("overflow.json")); }, {"overflow.json", "malformed JSON", "overflow"});
  testing::write_text_file(tmp.file("bad_utf8.json"), "{\"a\": \"\xff\"}");
  expect_input_error([&] { read_json_file(tmp.file("bad_utf8.json")); }, {"bad_utf8.json", "malformed JSON"});
  expect_input_error([&] { read_json_file(tmp.file("none.json")); }, {"none.json", "not found"});
  expect_input_error([&] { read_json_file(tmp.path().string()); }, {"folder"});
  testing::write_text_file(tmp.file("ok.json"), "{\"a\": [1, 2.5]}");
  EXPECT_DOUBLE_EQ(read_json_file(tmp.file("ok.json"))["a"][1].get<double>(), 2.5);
}

// ---------------------------------------------------------------- PLY mesh reader

TunnelMap one_wall_map() {
  TunnelMap m;
  m.detected = true;
  m.status = "ok";
  m.width_m = 0.8;
  m.height_m = 1.3;
  Wall& w = m.wall(WallClass::Top);
  w.found = true;
  w.boundary = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.8, 0, 1), Eigen::Vector3d(0.8, 0, 3),
                Eigen::Vector3d(0, 0, 3)};
  w.zones.push_back({ZoneKind::Forbidden, {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0.2, 0, 1),
                                           Eigen::Vector3d(0.2, 0, 3), Eigen::Vector3d(0, 0, 3)}});
  w.zones.push_back({ZoneKind::Traversable, {Eigen::Vector3d(0.2, 0, 1), Eigen::Vector3d(0.8, 0, 1),
                                             Eigen::Vector3d(0.8, 0, 3), Eigen::Vector3d(0.2, 0, 3)}});
  return m;
}

TEST(PlyMeshReader, ReadsOurMapPlyBack) {
  IoTempDir tmp;
  const std::string path = tmp.file("map.ply");
  write_map_ply(path, one_wall_map(), json{{"grow.angle_deg", 4.0}});
  const PlyMesh m = read_ply_mesh(path);
  // 2 zones + 4 border quads, 4 vertices and 2 triangles each.
  ASSERT_EQ(m.vertices.size(), 24u);
  ASSERT_EQ(m.triangles.size(), 12u);
  ASSERT_EQ(m.colors.size(), 24u);
  ASSERT_EQ(m.face_labels.size(), 12u);
  ASSERT_EQ(m.face_walls.size(), 12u);
  EXPECT_TRUE(m.normals.empty());
  EXPECT_TRUE((m.vertices[0] - Eigen::Vector3f(0, 0, 1)).norm() < 1e-6f);
  EXPECT_TRUE((m.vertices[5] - Eigen::Vector3f(0.8f, 0, 1)).norm() < 1e-6f);
  EXPECT_EQ(m.colors[0], (std::array<std::uint8_t, 3>{255, 140, 0}));   // forbidden orange
  EXPECT_EQ(m.colors[4], (std::array<std::uint8_t, 3>{220, 30, 30}));   // traversable red
  EXPECT_EQ(m.face_labels[0], int(MapFaceLabel::Forbidden));
  EXPECT_EQ(m.face_labels[2], int(MapFaceLabel::Traversable));
  EXPECT_EQ(m.face_labels[4], int(MapFaceLabel::Boundary));
  for (int w : m.face_walls) EXPECT_EQ(w, int(WallClass::Top));
  EXPECT_EQ(m.triangles[3], (std::array<std::int32_t, 3>{4, 6, 7}));
  bool has_param = false;
  for (const auto& c : m.comments) has_param |= c == "param grow.angle_deg 4";
  EXPECT_TRUE(has_param);
}

TEST(PlyMeshReader, ReadsOurFusedMeshAndPlanesPlyBack) {
  IoTempDir tmp;
  TriangleMesh mesh;
  for (int i = 0; i < 5; ++i) {
    mesh.vertices.emplace_back(0.5f * i, -1.25f * i, 3.f + i);
    mesh.normals.emplace_back(0, 0, 1);
    mesh.colors.push_back({std::uint8_t(10 * i), 20, std::uint8_t(250 - i)});
  }
  mesh.triangles = {{0, 1, 2}, {2, 3, 4}, {4, 0, 1}};
  write_mesh_ply(tmp.file("mesh.ply"), mesh);
  const PlyMesh m = read_ply_mesh(tmp.file("mesh.ply"));
  ASSERT_EQ(m.vertices.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(m.vertices[i], mesh.vertices[i]);
    EXPECT_EQ(m.normals[i], mesh.normals[i]);
    EXPECT_EQ(m.colors[i], mesh.colors[i]);
  }
  EXPECT_EQ(m.triangles, mesh.triangles);

  OrganizedCloud cloud;
  cloud.width = 3;
  cloud.height = 1;
  cloud.points = {{0.1f, 0.2f, 1.f}, {0.3f, 0.4f, 2.f}, {0.5f, 0.6f, 3.f}};
  PlaneSegments planes;
  planes.width = 3;
  planes.height = 1;
  planes.planes.resize(1);
  planes.planes[0].id = 7;
  planes.labels = {7, 0, 7};
  write_planes_ply(tmp.file("planes.ply"), cloud, planes, {WallClass::Left});
  const PlyMesh p = read_ply_mesh(tmp.file("planes.ply"));
  ASSERT_EQ(p.vertices.size(), 2u);
  EXPECT_EQ(p.vertices[1], cloud.points[2]);
  EXPECT_EQ(p.vertex_labels, (std::vector<std::int32_t>{7, 7}));
  EXPECT_TRUE(p.triangles.empty());
}

const char* kAsciiQuad =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 -2.5e-1\n4 0 1 2 3\n";

TEST(PlyMeshReader, ReadsAsciiAndTriangulatesPolygons) {
  const std::string text = kAsciiQuad;
  const PlyMesh m = parse_ply_mesh(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), "q.ply");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_FLOAT_EQ(m.vertices[3].z(), -0.25f);
  ASSERT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.triangles[1], (std::array<std::int32_t, 3>{0, 2, 3}));
}

TEST(PlyMeshReader, RefusesHostileFilesWithOneLine) {
  const auto parse = [](const std::string& text) {
    return parse_ply_mesh(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), "h.ply");
  };
  const auto expect = [&](const std::string& text, const std::string& part) {
    expect_input_error([&] { parse(text); }, {"h.ply", part});
  };
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect("hello", "not a PLY");
  expect("ply\nformat binary_big_endian 1.0\nend_header\n", "binary_big_endian");
  expect("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n",
         "truncated PLY: header promises");
  expect("ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n", "absurd element count");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "refers to vertex 7 of 3");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n200 0 1 2\n", "length");
  expect(head + face + "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", "vertex index");
  expect(head + face + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "PLY vertex 1 position is not finite");
  expect(head + face + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", "bad number 'zero'");
  expect(head + "property float x\n" + face, "declared twice");
  expect(head + "element face 1\nproperty list float int vertex_indices\nend_header\n", "list types must be integers");
  expect(head + "property uchar red\nproperty uchar green\nproperty uchar blue\n" + face + "0 0 0 1 2 3\n1 0 0 4 5 300\n0 1 0 1 1 1\n3 0 1 2\n",
         "bad value '300' for a uchar");
  expect("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no end_header");
  expect("ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n", "no vertex element");

  // Every truncation of a binary map PLY and of an ascii one: an InputError, never a crash.
  IoTempDir tmp;
  write_map_ply(tmp.file("map.ply"), one_wall_map(), json::object());
  const auto map = testing::read_binary_file(tmp.file("map.ply"));
  for (const std::string& full : {std::string(map.begin(), map.end()), std::string(kAsciiQuad)}) {
    for (std::size_t n = 0; n + 1 < full.size(); ++n) {
      const std::string cut = full.substr(0, n);
      if (n + 2 >= full.size() && full == kAsciiQuad) continue;  // "4 0 1 2 3" minus its newline is whole
      expect_input_error([&] { parse(cut); }, {"h.ply"});
    }
  }
}

TEST(PlyMeshReader, RandomByteFlipsNeverEscapeAsAnythingButInputError) {
  IoTempDir tmp;
  write_map_ply(tmp.file("map.ply"), one_wall_map(), json::object());
  const auto map = testing::read_binary_file(tmp.file("map.ply"));
  std::mt19937 rng(8);
  int refused = 0, read = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::uint8_t> bytes(map.begin(), map.end());
    for (int k = 0; k < 3; ++k) bytes[rng() % bytes.size()] = static_cast<std::uint8_t>(rng());
    try {
      const PlyMesh m = parse_ply_mesh(bytes.data(), bytes.size(), "flip.ply");
      for (const auto& t : m.triangles)
        for (int v : t) ASSERT_LT(static_cast<std::size_t>(v), m.vertices.size());
      ++read;
    } catch (const InputError& e) {
      ++refused;
      ASSERT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  }
  EXPECT_GT(refused, 100);
  EXPECT_GT(read, 100);
}

TEST(PlyMeshReader, MissingFileAndFolder) {
  IoTempDir tmp;
  expect_input_error([&] { read_ply_mesh(tmp.file("none.ply")); }, {"none.ply", "not found"});
  expect_input_error([&] { read_ply_mesh(tmp.path().string()); }, {"folder"});
}

// ---------------------------------------------------------------- real frames

struct RealFrame {
  const char* file;
  Intrinsics k;  // from resources/real-frames/SOURCES.md
  double min_valid_fraction;
  float min_mm, max_mm;
};

TEST(RealFrames, ReadWithSaneValidFractionAndDepthRange) {
  const RealFrame frames[] = {
      {"cape_tunnel_depth.png", {575.927, 576.408, 315.150, 230.586, 640, 480}, 0.7, 500, 8000},
      {"pcl_office_depth.png", {525, 525, 320, 240, 640, 480}, 0.7, 500, 8000},
      {"rtabmap_lab_depth_17.png", {525, 525, 319.5, 239.5, 640, 480}, 0.7, 500, 8000},
  };
  for (const RealFrame& rf : frames) {
    const std::string path = std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/" + rf.file;
    ReadOptions opt;
    opt.intrinsics = rf.k;
    const DepthFrame f = read_depth_png(path, opt);
    ASSERT_EQ(f.width, 640);
    ASSERT_EQ(f.height, 480);
    EXPECT_DOUBLE_EQ(f.intrinsics.fx, rf.k.fx);
    EXPECT_DOUBLE_EQ(f.intrinsics.cy, rf.k.cy);
    std::size_t valid = 0;
    float lo = std::numeric_limits<float>::max(), hi = 0;
    for (float d : f.depth)
      if (d > 0) {
        ++valid;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
    const double fraction = double(valid) / f.depth.size();
    std::printf("%s: valid %.3f, depth %.3f .. %.3f m\n", rf.file, fraction, lo / 1000.0, hi / 1000.0);
    EXPECT_GT(fraction, rf.min_valid_fraction) << rf.file;
    EXPECT_GE(lo, rf.min_mm) << rf.file;
    EXPECT_LE(hi, rf.max_mm) << rf.file;
  }
}

}  // namespace
}  // namespace tunnelmap
