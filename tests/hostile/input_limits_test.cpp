// Inputs that claim absurd sizes are refused at once, with one line naming the file, inside
// the memory limit: deep JSON nesting, a million frames, a huge image, a pose at 1e308 m.
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

}  // namespace
}  // namespace tunnelmap::hostile
