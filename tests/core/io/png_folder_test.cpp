// A plain folder of depth PNGs read as a sequence: natural order, defaults as for one PNG, the
// same frames as the files read one by one, and clear errors for folders with nothing to read.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/io/depth_png.h"
#include "core/io/frame_source.h"
#include "core/io/png_folder.h"
#include "core/util/build_paths.h"
#include "tests/support/cli_runner.h"
#include "tests/support/expect_input_error.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;
using testing::IoTempDir;
using testing::expect_input_error;
using testing::run_cli;
using testing::write_text_file;

const fs::path kLabDepth = fs::path(TUNNELMAP_TEST_DATA_DIR) / "sample/lab/depth";

// The three lab sample frames as scan2.png, scan10.png, scan1.png (their natural order is 1, 2,
// 10: sample frames 2, 0, 1), plus files that are not frames.
void make_folder(const IoTempDir& dir) {
  fs::copy_file(kLabDepth / "000000.png", dir.path() / "scan2.png");
  fs::copy_file(kLabDepth / "000001.png", dir.path() / "scan10.png");
  fs::copy_file(kLabDepth / "000002.png", dir.path() / "scan1.PNG");
  write_text_file(dir.file("notes.txt"), "not a frame\n");
  fs::create_directories(dir.path() / "sub");
  fs::copy_file(kLabDepth / "000000.png", dir.path() / "sub" / "scan0.png");
}

TEST(NaturalOrder, DigitRunsCompareByValue) {
  EXPECT_TRUE(natural_less("frame2.png", "frame10.png"));
  EXPECT_FALSE(natural_less("frame10.png", "frame2.png"));
  EXPECT_TRUE(natural_less("a.png", "b.png"));
  EXPECT_TRUE(natural_less("000009.png", "000010.png"));
  EXPECT_TRUE(natural_less("x99999999999999999999999.png", "x100000000000000000000000.png"));
  EXPECT_FALSE(natural_less("same.png", "same.png"));
}

TEST(PngFolder, ListsOnlyThePngsDirectlyInsideInNaturalOrder) {
  IoTempDir dir;
  make_folder(dir);
  const auto files = list_depth_pngs(dir.path().string());
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0]).filename(), "scan1.PNG");
  EXPECT_EQ(fs::path(files[1]).filename(), "scan2.png");
  EXPECT_EQ(fs::path(files[2]).filename(), "scan10.png");
}

TEST(PngFolder, OpensAsASequenceWhoseFramesEqualTheFilesReadOneByOne) {
  IoTempDir dir;
  make_folder(dir);
  const auto source = open_input(dir.path().string(), ReadOptions());
  ASSERT_EQ(source->size(), 3u);
  EXPECT_EQ(source->dataset(), nullptr);
  EXPECT_EQ(source->describe(2), "frame 2/3 (scan10.png)");
  const DepthFrame a = source->load(1);
  const DepthFrame b = read_depth_png((kLabDepth / "000000.png").string(), ReadOptions());
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_DOUBLE_EQ(a.intrinsics.fx, b.intrinsics.fx);  // the single-PNG default intrinsics
  EXPECT_FALSE(a.pose.has_value());
  EXPECT_EQ(fs::path(a.source).filename(), "scan2.png");
}

TEST(PngFolder, UserIntrinsicsAndDepthScaleApplyToEveryFrame) {
  IoTempDir dir;
  make_folder(dir);
  ReadOptions opt;
  Intrinsics k;
  k.fx = 500, k.fy = 501, k.cx = 300, k.cy = 200;
  opt.intrinsics = k;
  opt.depth_units_per_m = 5000;
  const auto source = open_input(dir.path().string(), opt);
  for (std::size_t i = 0; i < source->size(); ++i) {
    const DepthFrame f = source->load(i);
    EXPECT_DOUBLE_EQ(f.intrinsics.fx, 500);
    EXPECT_DOUBLE_EQ(f.intrinsics.cy, 200);
    EXPECT_DOUBLE_EQ(f.depth_units_per_m, 5000);
  }
}

TEST(PngFolder, AFolderWithNothingToReadNamesItselfAndWhatWasExpected) {
  IoTempDir dir;
  write_text_file(dir.file("readme.txt"), "x");
  expect_input_error([&] { open_input(dir.path().string(), ReadOptions()); },
                     {dir.path().string(), "no dataset.json", "no depth PNGs"});
}

TEST(PngFolder, ABadPngIsReportedWhenItsFrameIsLoadedNamingTheFile) {
  IoTempDir dir;
  make_folder(dir);
  write_text_file(dir.file("scan5.png"), "not a png");
  const auto source = open_input(dir.path().string(), ReadOptions());
  ASSERT_EQ(source->size(), 4u);
  EXPECT_NO_THROW(source->load(0));
  expect_input_error([&] { source->load(2); }, {"scan5.png"});
}

TEST(PngFolderCli, DetectRunsEveryFrameInNaturalOrder) {
  IoTempDir dir, out;
  make_folder(dir);
  const auto r = run_cli("detect " + dir.path().string() + " --json " + out.file("r.json") + " -q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto doc = nlohmann::json::parse(testing::slurp(out.file("r.json")));
  ASSERT_EQ(doc["frames"].size(), 3u);
  EXPECT_NE(doc["frames"][0]["source"].get<std::string>().find("scan1.PNG"), std::string::npos);
  EXPECT_NE(doc["frames"][2]["source"].get<std::string>().find("scan10.png"), std::string::npos);
  // Lab frames seen with the default intrinsics: the tunnel is found in each.
  for (const auto& f : doc["frames"]) EXPECT_EQ(f["status"], "ok") << f.dump();
}

}  // namespace
}  // namespace tunnelmap
