// TUM RGB-D sequences: list parsing, time association, pose interpolation, intrinsics from the
// folder name, the reader behind read_dataset/open_input, and the round trip through the CLI
// (simulate --format tum, convert) against the dataset.json layout.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <regex>
#include <sstream>

#include "core/io/readers.h"
#include "core/io/tum_associate.h"
#include "core/io/tum_camera.h"
#include "core/io/tum_list.h"
#include "core/io/tum_sequence.h"
#include "core/util/error.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/cli_runner.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::IoTempDir;
using testing::expect_input_error;
using testing::run_cli;
using testing::write_text_file;


TumPoseEntry sample(double t, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  TumPoseEntry s;
  s.timestamp_s = t;
  s.translation = p;
  s.rotation = q;
  return s;
}

// ---------------------------------------------------------------- list parser

TEST(TumList, SkipsCommentsAndBlankLinesAndKeepsLineNumbers) {
  const std::string text =
      "# color images\r\n# timestamp filename\r\n\r\n1305031102.175304 rgb/1305031102.175304.png\r\n"
      "  1305031102.211214\trgb/1305031102.211214.png  \n";
  const auto list = parse_tum_file_list(text, "rgb.txt");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_DOUBLE_EQ(list[0].timestamp_s, 1305031102.175304);
  EXPECT_EQ(list[0].path, "rgb/1305031102.175304.png");
  EXPECT_EQ(list[0].line, 4);
  EXPECT_EQ(list[1].path, "rgb/1305031102.211214.png");
  EXPECT_EQ(list[1].line, 5);
  EXPECT_TRUE(parse_tum_file_list("# only a comment\n", "rgb.txt").empty());
}

TEST(TumList, AByteOrderMarkAndLoneCarriageReturnsAreReadAsWindowsAndOldMacEditorsMeanThem) {
  const std::string text = "\xEF\xBB\xBF# depth maps\r1.25 depth/a.png\r\r2.5 depth/b.png\r";
  const auto list = parse_tum_file_list(text, "depth.txt");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_DOUBLE_EQ(list[0].timestamp_s, 1.25);
  EXPECT_EQ(list[0].path, "depth/a.png");
  EXPECT_EQ(list[0].line, 2);
  EXPECT_DOUBLE_EQ(list[1].timestamp_s, 2.5);
  EXPECT_EQ(list[1].line, 4);
  // A data line right after the mark: the mark is not part of the timestamp.
  const auto gt = parse_tum_groundtruth("\xEF\xBB\xBF" "1.5 1 2 3 0 0 0.6 0.8\r\n", "groundtruth.txt");
  ASSERT_EQ(gt.size(), 1u);
  EXPECT_DOUBLE_EQ(gt[0].timestamp_s, 1.5);
}

TEST(TumList, GroundTruthIsXyzThenQxQyQzQw) {
  const auto gt = parse_tum_groundtruth("# timestamp tx ty tz qx qy qz qw\n1.5 1 2 3 0 0 0.6 0.8\n", "gt.txt");
  ASSERT_EQ(gt.size(), 1u);
  EXPECT_EQ(gt[0].line, 2);
  EXPECT_EQ(gt[0].translation, Eigen::Vector3d(1, 2, 3));
  EXPECT_DOUBLE_EQ(gt[0].rotation.w(), 0.8);
  EXPECT_DOUBLE_EQ(gt[0].rotation.z(), 0.6);
  EXPECT_DOUBLE_EQ(gt[0].rotation.x(), 0.0);
}

TEST(TumList, BadLinesAreOneLineErrorsWithTheLineNumber) {
  const std::string head = "# header\n1.0 depth/a.png\n";
  expect_input_error([&] { parse_tum_file_list(head + "2.0\n", "depth.txt"); },
                     {"depth.txt: line 3:", "expected 'timestamp path'", "got 1 field"});
  expect_input_error([&] { parse_tum_file_list(head + "2.0 a.png b.png\n", "depth.txt"); },
                     {"line 3:", "got 3 fields"});
  expect_input_error([&] { parse_tum_file_list(head + "two depth/b.png\n", "depth.txt"); },
                     {"line 3:", "timestamp 'two' is not a finite number"});
  expect_input_error([&] { parse_tum_file_list(head + "nan depth/b.png\n", "depth.txt"); },
                     {"line 3:", "not a finite number"});
  expect_input_error([&] { parse_tum_file_list(head + "0.5 depth/b.png\n", "depth.txt"); },
                     {"line 3:", "timestamp 0.5 is not after the previous line's 1.0"});
  expect_input_error([&] { parse_tum_file_list(head + "1.0 depth/b.png\n", "depth.txt"); },
                     {"line 3:", "not after"});
  expect_input_error([&] { parse_tum_file_list(std::string("1.0 a\x01\xff.png x\n"), "depth.txt"); },
                     {"line 1:", "got 3 fields"});

  const std::string gt = "1.0 0 0 0 0 0 0 1\n";
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 0 0 0 0 0 1\n", "groundtruth.txt"); },
                     {"groundtruth.txt: line 2:", "timestamp tx ty tz qx qy qz qw", "got 7 fields"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 0 0 0 0 0 0 2\n", "groundtruth.txt"); },
                     {"line 2:", "quaternion (qx qy qz qw) has norm 2"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 0 0 0 0 0 0 0\n", "groundtruth.txt"); },
                     {"line 2:", "has norm 0"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 0 0 0 nan 0 0 1\n", "groundtruth.txt"); },
                     {"line 2:", "qx 'nan' is not a finite number"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 1e400 0 0 0 0 0 1\n", "groundtruth.txt"); },
                     {"line 2:", "tx"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "2.0 0 -2e9 0 0 0 0 1\n", "groundtruth.txt"); },
                     {"line 2:", "ty '-2e9' is out of range"});
  expect_input_error([&] { parse_tum_groundtruth(gt + "0.9 0 0 0 0 0 0 1\n", "groundtruth.txt"); },
                     {"line 2:", "not after"});
  // Four decimals, as the benchmark's files: close enough to 1, normalised.
  const auto ok = parse_tum_groundtruth("1 0 0 0 0.7071 0 0 0.7071\n", "groundtruth.txt");
  EXPECT_NEAR(ok[0].rotation.norm(), 1.0, 1e-15);
}

// ---------------------------------------------------------------- association

TEST(TumAssociate, NearestWithinTheLimitElseUnmatched) {
  // Binary-exact times, so that the gaps are exact: 1/128 s = 0.0078125 s.
  const std::vector<double> depth = {1.0, 2.0, 3.0, 4.0};
  const std::vector<double> rgb = {0.9921875, 1.0234375, 2.015625, 3.5, 4.03125};
  const std::vector<int> m = associate_nearest(depth, rgb, 0.02);
  EXPECT_EQ(m, (std::vector<int>{0, 2, -1, -1}));  // 4.0: 0.03125 s away is beyond 0.02
  EXPECT_EQ(associate_nearest(depth, rgb, 0.04), (std::vector<int>{0, 2, -1, 4}));
  EXPECT_EQ(associate_nearest(depth, {}, 0.02), (std::vector<int>{-1, -1, -1, -1}));
  EXPECT_TRUE(associate_nearest({}, rgb, 0.02).empty());
  // The limit is inclusive.
  EXPECT_EQ(associate_nearest({1.0}, {1.015625}, 0.015625), (std::vector<int>{0}));
}

TEST(TumAssociate, TiesGoToTheEarlierCandidateAndEachCandidateIsUsedOnce) {
  // Equidistant colour images: the earlier one.
  EXPECT_EQ(associate_nearest({1.0}, {0.9921875, 1.0078125}, 0.02), (std::vector<int>{0}));
  // Two depth frames equally near one colour image: the earlier depth frame gets it.
  EXPECT_EQ(associate_nearest({1.0, 1.015625}, {1.0078125}, 0.02), (std::vector<int>{0, -1}));
  // Closest pairs first (associate.py): the second depth frame is nearer, so it wins even
  // though the first asks first; the first then takes the other image within the limit.
  EXPECT_EQ(associate_nearest({1.0, 1.0078125}, {0.9921875, 1.0078125}, 0.02), (std::vector<int>{0, 1}));
  EXPECT_EQ(associate_nearest({1.0, 1.0078125}, {1.005859375}, 0.02), (std::vector<int>{-1, 0}));
}

// ---------------------------------------------------------------- interpolation

TEST(TumInterpolate, LinearTranslationAndSlerpHalfwayBetweenTwoRotations) {
  const Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond q1(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  const std::vector<TumPoseEntry> gt = {sample(0.0, {0, 0, 0}, q0), sample(1.0, {2, 4, -6}, q1)};
  const auto mid = interpolate_pose(gt, 0.5, 0.02);  // 0.5 s from either line: still bracketed
  ASSERT_TRUE(mid);
  EXPECT_TRUE(mid->translation().isApprox(Eigen::Vector3d(1, 2, -3), 1e-12));
  // Halfway between 0 and 90 degrees about z is 45 degrees about z.
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((mid->linear() - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(mid->linear()(0, 0), std::sqrt(0.5), 1e-12);

  // A quarter of the way from 0 to 120 degrees about x: 30 degrees.
  const std::vector<TumPoseEntry> gx = {
      sample(10.0, {0, 0, 0}, q0),
      sample(12.0, {0, 0, 0}, Eigen::Quaterniond(Eigen::AngleAxisd(2 * M_PI / 3, Eigen::Vector3d::UnitX())))};
  const auto quarter = interpolate_pose(gx, 10.5, 0.02);
  ASSERT_TRUE(quarter);
  const Eigen::AngleAxisd aa(quarter->linear());
  EXPECT_NEAR(aa.angle(), M_PI / 6, 1e-12);
  EXPECT_TRUE(aa.axis().isApprox(Eigen::Vector3d::UnitX(), 1e-12));

  // On a line: that line's pose exactly.
  const auto at1 = interpolate_pose(gt, 1.0, 0.02);
  ASSERT_TRUE(at1);
  EXPECT_EQ(at1->translation(), Eigen::Vector3d(2, 4, -6));
  EXPECT_TRUE(at1->linear().isApprox(q1.toRotationMatrix(), 1e-15));
}

TEST(TumInterpolate, OutsideTheGroundTruthOnlyWithinTheLimitOfAnEnd) {
  const Eigen::Quaterniond q0 = Eigen::Quaterniond::Identity();
  const std::vector<TumPoseEntry> gt = {sample(1.0, {1, 0, 0}, q0), sample(2.0, {2, 0, 0}, q0)};
  const auto before = interpolate_pose(gt, 0.984375, 0.02);  // 1/64 s before the first line
  ASSERT_TRUE(before);
  EXPECT_EQ(before->translation(), Eigen::Vector3d(1, 0, 0));  // held, not extrapolated
  const auto after = interpolate_pose(gt, 2.015625, 0.02);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->translation(), Eigen::Vector3d(2, 0, 0));
  EXPECT_FALSE(interpolate_pose(gt, 0.96875, 0.02));  // 1/32 s before: refused
  EXPECT_FALSE(interpolate_pose(gt, 2.03125, 0.02));
  EXPECT_FALSE(interpolate_pose(gt, 5.0, 0.02));
  EXPECT_TRUE(interpolate_pose(gt, 2.03125, 0.04));
  EXPECT_FALSE(interpolate_pose({}, 1.0, 0.02));
}

// ---------------------------------------------------------------- intrinsics from the name

TEST(TumCamera, FreiburgIntrinsicsFromTheFolderName) {
  const auto fr1 = tum_camera_from_folder_name("rgbd_dataset_freiburg1_desk");
  ASSERT_TRUE(fr1);
  EXPECT_EQ(fr1->name, "freiburg1");
  EXPECT_DOUBLE_EQ(fr1->intrinsics.fx, 517.3);
  EXPECT_DOUBLE_EQ(fr1->intrinsics.fy, 516.5);
  EXPECT_DOUBLE_EQ(fr1->intrinsics.cx, 318.6);
  EXPECT_DOUBLE_EQ(fr1->intrinsics.cy, 255.3);
  EXPECT_EQ(fr1->intrinsics.width, 640);
  EXPECT_EQ(fr1->intrinsics.height, 480);
  const auto fr2 = tum_camera_from_folder_name("rgbd_dataset_freiburg2_xyz");
  ASSERT_TRUE(fr2);
  EXPECT_DOUBLE_EQ(fr2->intrinsics.fx, 520.9);
  EXPECT_DOUBLE_EQ(fr2->intrinsics.fy, 521.0);
  EXPECT_DOUBLE_EQ(fr2->intrinsics.cx, 325.1);
  EXPECT_DOUBLE_EQ(fr2->intrinsics.cy, 249.7);
  const auto fr3 = tum_camera_from_folder_name("rgbd_dataset_freiburg3_long_office_household");
  ASSERT_TRUE(fr3);
  EXPECT_DOUBLE_EQ(fr3->intrinsics.fx, 535.4);
  EXPECT_DOUBLE_EQ(fr3->intrinsics.fy, 539.2);
  EXPECT_DOUBLE_EQ(fr3->intrinsics.cx, 320.1);
  EXPECT_DOUBLE_EQ(fr3->intrinsics.cy, 247.6);
  EXPECT_FALSE(tum_camera_from_folder_name("my_tunnel_run"));
  EXPECT_FALSE(tum_camera_from_folder_name("freiburg4"));
}

// ---------------------------------------------------------------- the reader

// A small TUM sequence on disk: 640x480 depth frames at 5000 units per metre.
struct TumFolder {
  IoTempDir tmp;
  fs::path dir;
  explicit TumFolder(const std::string& name = "rgbd_dataset_freiburg3_test") : dir(tmp.path() / name) {
    fs::create_directories(dir / "depth");
    fs::create_directories(dir / "rgb");
  }
  void depth(const std::string& rel, std::uint16_t value = 7500) const {
    ASSERT_TRUE(cv::imwrite((dir / rel).string(), cv::Mat(480, 640, CV_16UC1, cv::Scalar(value))));
  }
  void rgb(const std::string& rel) const {
    ASSERT_TRUE(cv::imwrite((dir / rel).string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar(10, 20, 30))));
  }
  void list(const std::string& name, const std::string& text) const {
    write_text_file((dir / name).string(), text);
  }
  std::string path() const { return dir.string(); }
};

// Three depth frames (1, 2, 3 s), colour near the first only, ground truth from 0.99 to 2 s.
void write_three_frames(const TumFolder& s) {
  for (const char* d : {"depth/1.png", "depth/2.png", "depth/3.png"}) s.depth(d);
  s.rgb("rgb/1.01.png");
  s.rgb("rgb/2.5.png");
  s.list("depth.txt", "# depth maps\n1.0 depth/1.png\n2.0 depth/2.png\n3.0 depth/3.png\n");
  s.list("rgb.txt", "# color images\n1.01 rgb/1.01.png\n2.5 rgb/2.5.png\n");
  s.list("groundtruth.txt", "# timestamp tx ty tz qx qy qz qw\n0.99 0 0 1 0 0 0 1\n2.0 1 0 1 0 0 0 1\n");
}

TEST(TumSequence, ReadsIntoADatasetWithPairingPosesAndUnmatchedCounts) {
  TumFolder s;
  write_three_frames(s);
  ASSERT_TRUE(is_tum_sequence(s.path()));
  ASSERT_TRUE(is_tum_sequence((s.dir / "depth.txt").string()));
  std::vector<std::string> notes;
  ReadOptions opt;
  opt.note = [&](const std::string& line) { notes.push_back(line); };
  const Dataset d = read_dataset(s.path(), opt);
  ASSERT_EQ(d.frames.size(), 3u);
  EXPECT_DOUBLE_EQ(d.depth_scale, 5000.0);
  EXPECT_EQ(d.up, Eigen::Vector3d::UnitZ());
  EXPECT_DOUBLE_EQ(d.intrinsics.fx, 535.4);  // freiburg3 by name
  EXPECT_EQ(d.intrinsics.width, 640);
  EXPECT_EQ(fs::path(d.json_path).filename(), "depth.txt");

  EXPECT_EQ(fs::path(d.frames[0].rgb_path).filename(), "1.01.png");
  EXPECT_TRUE(d.frames[1].rgb_path.empty());  // 2.5 is 0.5 s away
  EXPECT_TRUE(d.frames[2].rgb_path.empty());
  ASSERT_TRUE(d.frames[0].pose);
  EXPECT_TRUE(d.frames[0].pose->translation().isApprox(Eigen::Vector3d(0.01 / 1.01, 0, 1), 1e-9));
  ASSERT_TRUE(d.frames[1].pose);
  EXPECT_EQ(d.frames[1].pose->translation(), Eigen::Vector3d(1, 0, 1));
  EXPECT_FALSE(d.frames[2].pose);  // 1 s after the last ground truth
  EXPECT_EQ(d.unmatched.rgb, 2u);
  EXPECT_EQ(d.unmatched.pose, 1u);
  ASSERT_EQ(d.unmatched.notes.size(), 3u);
  EXPECT_NE(d.unmatched.notes[2].find("frame 2 (depth/3.png, depth.txt line 4): no ground truth within 0.02 s"),
            std::string::npos) << d.unmatched.notes[2];
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("2 of 3 depth frames have no colour image within 0.02 s (frames 1, 2)"), std::string::npos)
      << notes[0];
  EXPECT_NE(notes[0].find("1 of 3 have no ground-truth pose within 0.02 s (frame 2)"), std::string::npos) << notes[0];

  const DepthFrame f = d.load_frame(0);
  EXPECT_EQ(f.width, 640);
  EXPECT_TRUE(f.has_rgb());
  EXPECT_DOUBLE_EQ(f.depth_units_per_m, 5000.0);
  EXPECT_FLOAT_EQ(f.depth_m(3, 4), 1.5f);
  EXPECT_DOUBLE_EQ(f.timestamp_s, 1.0);
  EXPECT_FALSE(d.load_frame(1).has_rgb());

  // A wider limit: the colour image at 2.5 s is 0.5 s from both later frames; the earlier wins.
  opt.max_time_diff_s = 0.6;
  const Dataset wide = read_dataset(s.path(), opt);
  EXPECT_EQ(fs::path(wide.frames[1].rgb_path).filename(), "2.5.png");
  EXPECT_TRUE(wide.frames[2].rgb_path.empty());
  EXPECT_EQ(wide.unmatched.rgb, 1u);
}

TEST(TumSequence, OptionsOverrideScaleIntrinsicsAndUp) {
  TumFolder s("my_run");
  write_three_frames(s);
  expect_input_error([&] { read_dataset(s.path(), ReadOptions()); },
                     {"depth.txt", "no camera intrinsics", "'my_run'", "freiburg", "--intrinsics FX,FY,CX,CY"});
  ReadOptions opt;
  opt.intrinsics = Intrinsics{600, 601, 320, 240, 0, 0};
  opt.depth_units_per_m = 1000;
  opt.depth_scale_given = true;
  opt.world_up = Eigen::Vector3d(0, 0, -2);
  const Dataset d = read_dataset(s.path(), opt);
  EXPECT_DOUBLE_EQ(d.intrinsics.fx, 600);
  EXPECT_EQ(d.intrinsics.width, 640);  // from the images
  EXPECT_EQ(d.intrinsics.height, 480);
  EXPECT_DOUBLE_EQ(d.depth_scale, 1000);
  EXPECT_EQ(d.up, Eigen::Vector3d(0, 0, -1));

  // The same options through open_input; a dataset.json beside depth.txt wins.
  const auto src = open_input(s.path(), opt);
  ASSERT_NE(src->dataset(), nullptr);
  EXPECT_EQ(src->size(), 3u);
  EXPECT_EQ(src->describe(1), "frame 1/3 (depth/2.png)");
  EXPECT_DOUBLE_EQ(src->load(0).depth_m(0, 0), 7.5f);

  // Without a pose list every frame simply has no pose, and nothing is "unmatched".
  fs::remove(s.dir / "groundtruth.txt");
  fs::remove(s.dir / "rgb.txt");
  const Dataset bare = read_dataset(s.path(), opt);
  EXPECT_FALSE(bare.frames[0].pose);
  EXPECT_EQ(bare.unmatched.pose, 0u);
  EXPECT_EQ(bare.unmatched.rgb, 0u);
}

TEST(TumSequence, BadSequencesNameTheListAndLine) {
  TumFolder s;
  write_three_frames(s);
  s.list("depth.txt", "1.0 depth/1.png\n2.0 depth/missing.png\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"depth.txt: line 2:", "file 'depth/missing.png' not found"});
  s.list("depth.txt", "1.0 ../outside.png\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"depth.txt: line 1:", "escapes the sequence folder"});
  s.list("depth.txt", "1.0 /etc/passwd\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"line 1:", "must be a path relative"});
  s.list("depth.txt", "# nothing\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"depth.txt", "lists no depth images"});
  s.list("depth.txt", "1.0 depth/1.png\n2.0 depth/2.png\n");
  s.list("rgb.txt", "1.0 rgb/1.01.png\n0.5 rgb/2.5.png\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"rgb.txt: line 2:", "not after"});
  s.list("rgb.txt", "1.0 rgb/1.01.png\n");
  s.list("groundtruth.txt", "1.0 0 0 0 0 0 0 1\n2.0 0 0 0 0.5 0.5 0.5 0.5 extra\n");
  expect_input_error([&] { read_dataset(s.path()); }, {"groundtruth.txt: line 2:", "got 9 fields"});
  s.list("groundtruth.txt", "1.0 0 0 0 0 0 0 1\n");
  s.list("tunnelmap.json", "{\"format\": \"other\"}");
  expect_input_error([&] { read_dataset(s.path()); }, {"tunnelmap.json", "key 'format'"});
  fs::remove(s.dir / "tunnelmap.json");

  // Image problems show when a frame is loaded, naming the list line.
  ASSERT_TRUE(cv::imwrite((s.dir / "depth/2.png").string(), cv::Mat(240, 320, CV_16UC1, cv::Scalar(1))));
  const Dataset d = read_dataset(s.path());
  expect_input_error([&] { d.load_frame(1); }, {"depth.txt: line 2:", "image is 320x240 but intrinsics say 640x480"});
  ASSERT_TRUE(cv::imwrite((s.dir / "rgb/1.01.png").string(), cv::Mat(240, 320, CV_8UC3, cv::Scalar(1))));
  expect_input_error([&] { d.load_frame(0); }, {"rgb.txt: line 1:", "image is 320x240 but the depth image is 640x480"});
}


// ---------------------------------------------------------------- the command line

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The printed line that starts with `prefix` (empty if none).
std::string line_starting(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return "";
}

// "fused ... : 123 vertices, 456 triangles" -> "123 vertices, 456 triangles"
std::string mesh_counts(const std::string& out) {
  std::smatch m;
  const std::string line = line_starting(out, "fused ");
  return std::regex_search(line, m, std::regex("[0-9]+ vertices, [0-9]+ triangles")) ? m.str() : "";
}

void expect_same_detections(const std::string& a_json, const std::string& b_json) {
  const auto a = read_json(a_json)["frames"], b = read_json(b_json)["frames"];
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["status"], b[i]["status"]) << "frame " << i;
    ASSERT_TRUE(a[i]["width_m"].is_number()) << "frame " << i;
    EXPECT_NEAR(a[i]["width_m"].get<double>(), b[i]["width_m"].get<double>(), 1e-6) << "frame " << i;
    EXPECT_NEAR(a[i]["height_m"].get<double>(), b[i]["height_m"].get<double>(), 1e-6) << "frame " << i;
  }
}

TEST(TumCli, SimulatedSequenceRoundTripsThroughTheTumLayout) {
  IoTempDir tmp;
  const std::string ds = tmp.file("sim"), tum = tmp.file("sim_tum"), conv = tmp.file("conv_tum"),
                    back = tmp.file("back");
  ASSERT_EQ(run_cli("simulate " + ds + " --frames 6 --seed 3 --quiet").exit_code, 0);
  auto r = run_cli("simulate " + tum + " --frames 6 --seed 3 --format tum");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("frame 6/6: " + tum + "/depth/0.166667.png"), std::string::npos) << r.out;
  r = run_cli("convert " + ds + " " + conv + " --to tum");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 6 frames (6 with colour, 6 with a pose) as a TUM RGB-D sequence"), std::string::npos);
  // Both ways to TUM write the same files.
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(tum)) {
    if (!e.is_regular_file()) continue;
    ++files;
    const fs::path rel = fs::relative(e.path(), tum);
    EXPECT_EQ(testing::read_binary_file(e.path().string()), testing::read_binary_file(conv + "/" + rel.string()))
        << rel;
  }
  // depth.txt, rgb.txt, groundtruth.txt, tunnelmap.json, the list of files written, images
  EXPECT_EQ(files, 5u + 6u + 6u);
  EXPECT_FALSE(fs::exists(fs::path(tum) / "dataset.json"));
  // The depth is 5 units per millimetre.
  const cv::Mat mm = cv::imread(ds + "/depth/000002.png", cv::IMREAD_UNCHANGED);
  const cv::Mat tu = cv::imread(tum + "/depth/0.066667.png", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(tu.type(), CV_16UC1);
  cv::Mat mm5;
  mm.convertTo(mm5, CV_16UC1, 5.0);
  EXPECT_EQ(cv::countNonZero(mm5 != tu), 0);
  // ... and back to a dataset, copied at 5000 units per metre.
  r = run_cli("convert " + tum + " " + back + " --to dataset -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_json(back + "/dataset.json")["depth_scale"], 5000.0);

  for (const std::string& in : {ds, tum, back}) {
    r = run_cli("detect " + in + " -q --json " + in + ".json");
    ASSERT_EQ(r.exit_code, 0) << in << ": " << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;  // every frame matched: no note
  }
  expect_same_detections(ds + ".json", tum + ".json");
  expect_same_detections(ds + ".json", back + ".json");

  // The fused mesh, with the default pose refinement and without it (16 mm voxels keep the test
  // fast): the same scene in either layout gives the same cloud bit for bit, so the same mesh.
  const std::string fuse = "fuse ", coarse = " --set fusion.voxel_mm=16";
  for (const std::string refine : {"", " --no-pose-refinement"}) {
    SCOPED_TRACE(refine);
    const auto fa = run_cli(fuse + ds + refine + " --mesh " + tmp.file("a.ply") + coarse);
    const auto fb = run_cli(fuse + tum + refine + " --mesh " + tmp.file("b.ply") + coarse);
    ASSERT_EQ(fa.exit_code, 0) << fa.err;
    ASSERT_EQ(fb.exit_code, 0) << fb.err;
    EXPECT_FALSE(mesh_counts(fa.out).empty()) << fa.out;
    EXPECT_EQ(mesh_counts(fa.out), mesh_counts(fb.out));
    const std::string truth = line_starting(fa.out, "mesh vs ground truth:");
    EXPECT_FALSE(truth.empty()) << fa.out;  // kept in tunnelmap.json
    EXPECT_EQ(truth, line_starting(fb.out, "mesh vs ground truth:"));
  }
}

// Gravity has no place in the TUM layout: tunnelmap.json keeps it by depth image, and a frame
// without it stays without.
TEST(TumCli, EachFramesGravityRoundTripsThroughTheSidecar) {
  IoTempDir tmp;
  const std::string ds = tmp.file("sim"), tum = tmp.file("tum"), back = tmp.file("back");
  ASSERT_EQ(run_cli("simulate " + ds + " --frames 4 --seed 5 --imu 0.5 --quiet").exit_code, 0);
  nlohmann::json doc = read_json(ds + "/dataset.json");
  doc["frames"][2].erase("gravity");
  write_text_file(ds + "/dataset.json", doc.dump(2));
  auto r = run_cli("convert " + ds + " " + tum + " --to tum -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_json(tum + "/tunnelmap.json")["gravity"].size(), 3u);
  r = run_cli("convert " + tum + " " + back + " --to dataset");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 with gravity"), std::string::npos) << r.out;
  const Dataset from_tum = read_dataset(tum);
  const auto written = read_json(back + "/dataset.json")["frames"];
  ASSERT_EQ(from_tum.frames.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const nlohmann::json& truth = doc["frames"][i];
    EXPECT_EQ(from_tum.frames[i].gravity.has_value(), truth.contains("gravity"));
    EXPECT_EQ(written[i].contains("gravity"), truth.contains("gravity"));
    if (!truth.contains("gravity")) continue;
    const Eigen::Vector3d g(truth["gravity"][0].get<double>(), truth["gravity"][1].get<double>(),
                            truth["gravity"][2].get<double>());
    EXPECT_LT((*from_tum.frames[i].gravity - g.normalized()).norm(), 1e-15);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(written[i]["gravity"][k].get<double>(), g.normalized()[k], 1e-15);
  }
  // A direction that is none is refused, naming the file and the frame's key.
  nlohmann::json side = read_json(tum + "/tunnelmap.json");
  const std::string first = side["gravity"].items().begin().key();
  side["gravity"][first] = {0, 0, 0};
  write_text_file(tum + "/tunnelmap.json", side.dump());
  expect_input_error([&] { read_dataset(tum); }, {tum + "/tunnelmap.json", "gravity." + first, "zero vector"});
}

TEST(TumCli, UnmatchedFramesAreReportedAndPoselessFramesRefusedByFuse) {
  TumFolder s;
  write_three_frames(s);
  auto r = run_cli("detect " + s.path() + " -q");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(testing::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("tunnelmap-cli: note: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 of 3 depth frames have no colour image"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("summary: "), std::string::npos);
  // A wider limit pairs more, and reaches past the end of the ground truth.
  r = run_cli("detect " + s.path() + " -q --max-time-diff 2");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 of 3 depth frames have no colour image within 2 s (frame 2)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("ground-truth"), std::string::npos) << r.err;
  r = run_cli("fuse " + s.path() + " --mesh " + s.tmp.file("m.ply"));
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("depth.txt: frames[2] has neither \"pose\" nor \"joints\""), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(s.tmp.file("m.ply")));
  r = run_cli("map " + s.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("frames[2]"), std::string::npos) << r.err;
}

TEST(TumCli, BadInputAndOptionsGiveOneLineErrorsAndNoOutput) {
  TumFolder s;
  write_three_frames(s);
  const std::string out = s.tmp.file("out");
  auto r = run_cli("detect " + s.path() + " --max-time-diff -1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--max-time-diff"), std::string::npos) << r.err;
  r = run_cli("detect " + s.path() + " --world-up 0,0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--world-up"), std::string::npos) << r.err;
  r = run_cli("convert " + s.path() + " " + out);
  EXPECT_EQ(r.exit_code, 2);  // --to is required
  r = run_cli("convert " + s.path() + " " + out + " --to ply");
  EXPECT_EQ(r.exit_code, 2);

  s.list("groundtruth.txt", "0.99 0 0 1 0 0 0 1\n2.0 1 0 1 0 0 0 2\n");
  for (const std::string& cmd : {"detect " + s.path() + " -q", "convert " + s.path() + " " + out + " --to dataset"}) {
    r = run_cli(cmd);
    EXPECT_EQ(r.exit_code, 3) << cmd;
    EXPECT_EQ(testing::count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("groundtruth.txt: line 2: quaternion (qx qy qz qw) has norm 2"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(out));

  // A frame that fails while converting: nothing is left behind, not even a staging folder.
  s.list("groundtruth.txt", "0.99 0 0 1 0 0 0 1\n");
  ASSERT_TRUE(cv::imwrite((s.dir / "depth/3.png").string(), cv::Mat(10, 10, CV_16UC1, cv::Scalar(1))));
  r = run_cli("convert " + s.path() + " " + out + " --to tum");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("depth.txt: line 4: image is 10x10"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(s.tmp.path()))
    EXPECT_EQ(e.path().filename().string().find(".out"), std::string::npos) << e.path();
  r = run_cli("convert " + s.path() + " " + s.tmp.file("new/sub/out") + " --to dataset");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(fs::exists(s.tmp.file("new")));  // nor the folders made for it

  // A non-empty output folder is refused, and a single depth image is no sequence.
  s.depth("depth/3.png");
  fs::create_directories(out);
  write_text_file(out + "/keep.txt", "mine");
  r = run_cli("convert " + s.path() + " " + out + " --to tum");
  EXPECT_EQ(r.exit_code, 2);  // bad usage, refused before any work
  EXPECT_NE(r.err.find("not empty"), std::string::npos) << r.err;
  EXPECT_EQ(testing::slurp(out + "/keep.txt"), "mine");
  r = run_cli("convert " + (s.dir / "depth/1.png").string() + " " + s.tmp.file("x") + " --to tum");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("convert reads a dataset folder"), std::string::npos) << r.err;
  // The sequence itself converts, into a new folder, with the poseless frame noted.
  r = run_cli("convert " + s.path() + " " + s.tmp.file("ok") + " --to tum");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("no pose"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tunnelmap
