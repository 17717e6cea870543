// The organised PCD reader: round trips with PCL, intrinsics estimation, hostile headers.
#include <gtest/gtest.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/io/organized_pcd.h"
#include "core/io/read_options.h"
#include "tests/core/io/io_fixtures.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

using testing::IoTempDir;
using testing::expect_input_error;
using testing::kPcdTruth;
using testing::organised_plane_cloud;

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

}  // namespace
}  // namespace tunnelmap
