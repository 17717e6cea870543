// Data problems are exit 3 and usage problems exit 2, each one line, however hostile the field
// the message echoes.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

using Messages = WithSmallDataset;

TEST_F(Messages, ZeroDepthScaleIsBadUsage) {
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", ds(), "-q", "--depth-scale", "0"}), 2, "--depth-scale"));
}

TEST_F(Messages, AHugeFieldIsCutAndControlCharactersEscaped) {
  const std::string hostile = std::string(100000, 'a') + "\n\r" + std::string(10, 'b') + ".png";
  edit_index([&](nlohmann::json& j) { j["frames"][1]["depth"] = hostile; });
  const Outcome o = run_cli({"detect", ds(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_LT(o.err.size(), 600u);
}

TEST_F(Messages, ANulInsideAFramePathIsRefused) {
  edit_index([](nlohmann::json& j) { j["frames"][1]["depth"] = std::string("depth/000001.png\0.txt", 21); });
  const Outcome o = run_cli({"detect", ds(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, index().string()));
  EXPECT_NE(o.err.find("NUL"), std::string::npos) << o.err;
}

// libpng's own "libpng error: …" line used to come first; its reason is now in the tool's line.
TEST_F(Messages, ACorruptPngIsOneLineWithLibpngsReason) {
  const std::filesystem::path png = dir() / "ds" / "depth" / "000001.png";
  std::vector<char> bytes;
  {
    std::ifstream in(png, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string file(bytes.begin(), bytes.end());
  const std::size_t idat = file.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  ASSERT_LT(idat + 60, bytes.size());
  bytes[idat + 50] = static_cast<char>(bytes[idat + 50] ^ 0xff);  // inside the compressed data
  std::ofstream(png, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const Outcome o = run_cli({"detect", png.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, png.string()));
  EXPECT_NE(o.err.find("corrupt PNG: "), std::string::npos) << o.err;
  EXPECT_EQ(o.err.find("libpng"), std::string::npos) << o.err;
}

// A simulated dataset of two frames with JPEG colour images; returns the second frame's JPEG.
std::filesystem::path jpeg_dataset(const std::filesystem::path& ds) {
  const Outcome made = run_cli({"simulate", ds.string(), "--frames", "2", "--rgb-format", "jpg", "--quiet"});
  EXPECT_EQ(made.exit_code, 0) << made.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(ds / "dataset.json"));
  return ds / j["frames"][1]["rgb"].get<std::string>();
}

// libjpeg's own "Premature end of JPEG file" warning used to reach stderr through OpenCV.
TEST_F(Messages, ATruncatedJpegColourFrameIsOneLineNamingIt) {
  const std::filesystem::path ds = dir() / "jpeg", jpg = jpeg_dataset(ds);
  const std::string bytes = read_file(jpg);
  ASSERT_GT(bytes.size(), 2000u);
  write_file(jpg, bytes.substr(0, bytes.size() / 2));
  const Outcome o = run_cli({"detect", ds.string(), "-q", "--json", (dir() / "r.json").string()});
  EXPECT_TRUE(exits_with_one_line(o, 3, jpg.string()));
  EXPECT_NE(o.err.find("corrupt JPEG: Premature end of JPEG file"), std::string::npos) << o.err;
  EXPECT_FALSE(std::filesystem::exists(dir() / "r.json"));
}

// Bytes between the scan and the end marker: libjpeg's "Corrupt JPEG data: ... extraneous bytes"
// (the scan decoder takes all but the last as data).
TEST_F(Messages, ExtraneousBytesInAJpegColourFrameAreOneLineNamingIt) {
  const std::filesystem::path ds = dir() / "jpeg", jpg = jpeg_dataset(ds);
  std::string bytes = read_file(jpg);
  ASSERT_EQ(bytes.substr(bytes.size() - 2), "\xff\xd9");
  bytes.insert(bytes.size() - 2, "garbage");
  write_file(jpg, bytes);
  const Outcome o = run_cli({"detect", ds.string(), "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, jpg.string()));
  EXPECT_NE(o.err.find("corrupt JPEG: Corrupt JPEG data: 1 extraneous bytes before marker 0xd9"), std::string::npos)
      << o.err;
}

TEST_F(Messages, AnIntactJpegColourDatasetIsRead) {
  const std::filesystem::path ds = dir() / "jpeg";
  jpeg_dataset(ds);
  const Outcome o = run_cli({"detect", ds.string(), "-q"});
  EXPECT_EQ(o.exit_code, 0) << o.err;
  EXPECT_TRUE(o.err.empty()) << o.err;
}

// Frames with no depth at all: nothing to fuse is a data problem naming the input, not a crash
// or an empty mesh.
TEST_F(Messages, FusingFramesWithNoDepthInRangeIsADataProblem) {
  for (const auto& entry : std::filesystem::directory_iterator(dir() / "ds" / "depth"))
    ASSERT_TRUE(cv::imwrite(entry.path().string(), cv::Mat::zeros(480, 640, CV_16UC1)));
  const std::filesystem::path mesh = dir() / "mesh.ply";
  const Outcome o = run_cli({"fuse", ds(), "--quiet", "--mesh", mesh.string()});
  EXPECT_TRUE(exits_with_one_line(o, 3, ds()));
  EXPECT_NE(o.err.find("no depth within"), std::string::npos) << o.err;
  EXPECT_FALSE(std::filesystem::exists(mesh));
}

// A surface that needs more memory than the volume's budget is refused before it is allocated:
// a data problem naming the input, for the sparse volume and the dense one alike.
TEST_F(Messages, AVolumeOverItsMemoryBudgetIsADataProblem) {
  for (const std::vector<std::string>& extra : {std::vector<std::string>{}, std::vector<std::string>{"--dense"}}) {
    const std::filesystem::path mesh = dir() / "mesh.ply";
    std::vector<std::string> args = {"fuse", ds(), "--quiet", "--no-pose-refinement", "--set",
                                     "fusion.max_volume_mb=1", "--mesh", mesh.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Outcome o = run_cli(args);
    EXPECT_TRUE(exits_with_one_line(o, 3, ds())) << o.err;
    EXPECT_NE(o.err.find("fusion.max_volume_mb = 1 MiB"), std::string::npos) << o.err;
    EXPECT_FALSE(std::filesystem::exists(mesh));
  }
}

// The summary line of `detect` (stdout's last line).
std::string summary(const Outcome& o) { return o.out.substr(o.out.rfind("summary:")); }

TEST_F(Messages, AnAbsurdUpVectorIsADataProblemNamingTheDataset) {
  for (const char* up : {"[0,0,0]", "[1e308,1e308,0]"}) {
    edit_index([&](nlohmann::json& j) { j["up"] = nlohmann::json::parse(up); });
    const Outcome o = run_cli({"detect", ds(), "-q"});
    EXPECT_TRUE(exits_with_one_line(o, 3, index().string())) << up;
    EXPECT_NE(o.err.find("key 'up'"), std::string::npos) << o.err;
  }
}

TEST_F(Messages, AnUpVectorOfAnyLengthIsItsDirection) {
  const Outcome unit = run_cli({"detect", ds(), "-q"});
  edit_index([](nlohmann::json& j) { j["up"] = nlohmann::json::array({0, 0, 2.5}); });
  const Outcome longer = run_cli({"detect", ds(), "-q"});
  ASSERT_EQ(unit.exit_code, 0) << unit.err;
  ASSERT_EQ(longer.exit_code, 0) << longer.err;
  EXPECT_EQ(summary(longer).substr(0, summary(longer).find(", median")), summary(unit).substr(0, summary(unit).find(", median")));
}

}  // namespace
}  // namespace tunnelmap::hostile
