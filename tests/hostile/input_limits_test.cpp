// Inputs that claim absurd sizes are refused at once, with one line naming the file, inside
// the memory limit: deep JSON nesting, a million frames, a huge image (over the parameter
// input.max_image_pixels), a pose at 1e308 m.
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

class InputLimits : public WithSmallDataset {
 protected:
  Outcome detect() const { return run_cli({"detect", ds(), "-q", "--json", (dir() / "r.json").string()}); }
};

TEST_F(InputLimits, DeepNestingInTheDatasetIsRefused) {
  std::string text = read_file(index());
  const std::string key = "\"ground_truth\":";
  const std::size_t at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + key.size(), std::string(100000, '[') + "0" + std::string(100000, ']') + ", \"x\":");
  write_file(index(), text);
  const Outcome o = detect();
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_NE(o.err.find("nested deeper"), std::string::npos) << o.err;
}

TEST_F(InputLimits, AMillionFramesAreRefused) {
  edit_index([](nlohmann::json& j) {
    const nlohmann::json depth = j["frames"][0]["depth"];
    j["frames"] = nlohmann::json::array();
    for (int i = 0; i < 1000000; ++i) j["frames"].push_back({{"depth", depth}});
  });
  const Outcome o = detect();
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_LT(o.max_rss_kb, 1500 * 1024) << "peak RSS";
}

TEST_F(InputLimits, AnAbsurdPoseIsRefused) {
  edit_index([](nlohmann::json& j) { j["frames"][1]["pose"][3] = 1e308; });
  const Outcome o = detect();
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_NE(o.err.find("out of range"), std::string::npos) << o.err;
}

// 50 km is a valid pose, but no volume spans it: refused from the poses alone, before the
// frames are detected and mapped (30 frames with one of them 50 km away took 80 s).
TEST_F(InputLimits, AFrameFarFromTheOthersIsRefusedBeforeFusing) {
  const fs::path walk = dir() / "walk";
  ASSERT_EQ(run_cli({"simulate", walk.string(), "--preset", "lab", "--frames", "30", "--quiet"}).exit_code, 0);
  const fs::path index = walk / "dataset.json";
  nlohmann::json j = nlohmann::json::parse(read_file(index));
  j["frames"][15]["pose"][3] = 5e4;
  write_file(index, j.dump());
  const Outcome o = run_cli({"fuse", walk.string(), "--json", (dir() / "f.json").string()});
  EXPECT_TRUE(exits_with_one_line(o, 3, walk.string()));
  EXPECT_NE(o.err.find("fusion.max_extent_m"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(dir() / "f.json"));
}

TEST_F(InputLimits, AHugeImageIsRefusedBeforeDecoding) {
  const fs::path png = dir() / "huge.png";
  ASSERT_TRUE(cv::imwrite(png.string(), cv::Mat::zeros(5000, 5000, CV_16UC1)));
  const Outcome o = run_cli({"detect", png.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, png.string()));
  EXPECT_LT(o.max_rss_kb, 300 * 1024) << "peak RSS: decoded anyway?";
}

// Sparse: 257 MB on paper, a few kilobytes on disk; refused from its size, before parsing.
TEST_F(InputLimits, AJsonFileOver256MbIsRefused) {
  const std::string text = read_file(index());
  write_file(index(), text);
  fs::resize_file(index(), 257ull << 20);
  const Outcome o = detect();
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_NE(o.err.find("too large"), std::string::npos) << o.err;
  EXPECT_LT(o.max_rss_kb, 300 * 1024) << "peak RSS: read anyway?";
}

TEST_F(InputLimits, AnAbsurdTumGroundTruthPoseIsRefused) {
  const fs::path tum = dir() / "tum";
  ASSERT_EQ(run_cli({"convert", ds(), tum.string(), "--to", "tum", "-q"}).exit_code, 0);
  const fs::path gt = tum / "groundtruth.txt";
  std::string text = read_file(gt);
  // The first pose line's tx (the field after the timestamp) becomes 1e308 m.
  std::size_t line = 0;
  while (text[line] == '#') line = text.find('\n', line) + 1;
  const std::size_t tx = text.find(' ', line) + 1, end = text.find(' ', tx);
  text.replace(tx, end - tx, "1e308");
  write_file(gt, text);
  const Outcome o = run_cli({"detect", tum.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, gt.string()));
  EXPECT_NE(o.err.find("out of range"), std::string::npos) << o.err;
}

// The limit is the parameter input.max_image_pixels: 8192 x 8192 is over its default.
TEST_F(InputLimits, TheDefaultPixelLimitRefusesAn8192By8192Image) {
  const fs::path png = dir() / "bomb.png";
  ASSERT_TRUE(cv::imwrite(png.string(), cv::Mat::zeros(8192, 8192, CV_16UC1)));
  const Outcome o = run_cli({"detect", png.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, png.string()));
  EXPECT_NE(o.err.find("8192x8192 pixels is too large (at most 16777216 = 16.8 Mpx, input.max_image_pixels)"),
            std::string::npos)
      << o.err;
  EXPECT_LT(o.max_rss_kb, 300 * 1024) << "peak RSS: decoded anyway?";
}

TEST_F(InputLimits, ALoweredPixelLimitRefusesAnImageJustOverIt) {
  const fs::path over = dir() / "over.png", at = dir() / "at.png";
  ASSERT_TRUE(cv::imwrite(over.string(), cv::Mat(65, 64, CV_16UC1, cv::Scalar(1000))));  // 4160 px
  ASSERT_TRUE(cv::imwrite(at.string(), cv::Mat(64, 64, CV_16UC1, cv::Scalar(1000))));    // 4096 px
  const std::string limit = "input.max_image_pixels=4096";
  const Outcome refused = run_cli({"detect", over.string(), "-q", "--set", limit, "--json", (dir() / "o.json").string()});
  EXPECT_TRUE(exits_with_one_line(refused, 3, over.string()));
  EXPECT_NE(refused.err.find("64x65 pixels is too large (at most 4096 = 0.0 Mpx"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(dir() / "o.json"));
  const Outcome accepted = run_cli({"detect", at.string(), "-q", "--set", limit, "--json", (dir() / "a.json").string()});
  EXPECT_EQ(accepted.exit_code, 0) << accepted.err;
  EXPECT_TRUE(accepted.err.empty()) << accepted.err;
  EXPECT_TRUE(fs::exists(dir() / "a.json"));
  // Without the lowered limit both are far under the default.
  EXPECT_EQ(run_cli({"detect", over.string(), "-q"}).exit_code, 0);
}

TEST_F(InputLimits, ALoweredPixelLimitReachesTheFramesOfADataset) {
  // The small dataset's frames are 640x480 = 307200 pixels.
  const Outcome refused = run_cli({"detect", ds(), "-q", "--set", "input.max_image_pixels=307199"});
  EXPECT_TRUE(exits_with_one_line(refused, 3, ds()));
  EXPECT_NE(refused.err.find("640x480 pixels is too large (at most 307199"), std::string::npos) << refused.err;
  EXPECT_EQ(run_cli({"detect", ds(), "-q", "--set", "input.max_image_pixels=307200"}).exit_code, 0);
}

TEST_F(InputLimits, APixelLimitOutsideItsRangeIsBadUsage) {
  const Outcome o = run_cli({"detect", ds(), "-q", "--set", "input.max_image_pixels=67108865"});
  EXPECT_EQ(o.exit_code, 2) << o.err;
  EXPECT_NE(o.err.find("input.max_image_pixels"), std::string::npos) << o.err;
}

}  // namespace
}  // namespace tunnelmap::hostile
