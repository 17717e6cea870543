// File and folder names up to the file system's 255-byte limit work as inputs and outputs
// (the temporary names beside an output are cut to fit); a longer output name is bad usage,
// refused before any work.
#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

using LongNames = WithSmallDataset;

TEST_F(LongNames, AnInputNamed255BytesIsRead) {
  const fs::path png = dir() / (std::string(251, 'a') + ".png");
  fs::copy_file(dir() / "ds" / "depth" / "000000.png", png);
  const Outcome o = run_cli({"detect", png.string(), "-q"});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("summary: 1/1 frames"), std::string::npos) << o.out;
}

TEST_F(LongNames, OutputsNamed255BytesAreWrittenWithoutLeftovers) {
  const fs::path json = dir() / (std::string(250, 'b') + ".json");
  const Outcome detect = run_cli({"detect", ds(), "-q", "--json", json.string()});
  EXPECT_EQ(detect.exit_code, 0) << detect.err;
  EXPECT_TRUE(fs::is_regular_file(json));
  const fs::path folder = dir() / std::string(255, 'c');
  const Outcome convert = run_cli({"convert", ds(), folder.string(), "--to", "tum", "-q"});
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_TRUE(fs::is_regular_file(folder / "depth.txt"));
  EXPECT_TRUE(leftovers(dir()).empty());
}

TEST_F(LongNames, AnOutputNameOverTheLimitIsBadUsage) {
  const fs::path json = dir() / (std::string(252, 'd') + ".json");
  const Outcome o = run_cli({"detect", ds(), "-q", "--json", json.string()});
  EXPECT_TRUE(exits_with_one_line(o, 2, json.string()));
  EXPECT_NE(o.err.find("257 bytes, over the limit of 255"), std::string::npos) << o.err;
  EXPECT_EQ(o.out, "");  // refused before any work
}

}  // namespace
}  // namespace tunnelmap::hostile
