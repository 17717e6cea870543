// open_input: the dispatcher from a path (PNG, PCD, dataset folder or json, sniffed content) to
// a frame source.
#include <gtest/gtest.h>

#include <pcl/io/pcd_io.h>

#include <filesystem>
#include <string>

#include "core/io/frame_source.h"
#include "tests/core/io/io_fixtures.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::DatasetFixture;
using testing::expect_input_error;
using testing::kDsW;
using testing::organised_plane_cloud;

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
  // The dataset's depth folder alone is a plain folder of depth PNGs: a sequence without poses.
  const auto folder = open_input(ds.tmp.file("depth"), {});
  EXPECT_EQ(folder->size(), 2u);
  EXPECT_EQ(folder->dataset(), nullptr);
  EXPECT_FALSE(folder->load(1).pose.has_value());
  fs::create_directories(ds.tmp.file("empty"));
  expect_input_error([&] { open_input(ds.tmp.file("empty"), {}); }, {"no dataset.json"});
}

}  // namespace
}  // namespace tunnelmap
