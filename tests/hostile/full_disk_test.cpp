// A full disk, simulated by a file size limit (writes past it fail with EFBIG, SIGXFSZ is
// ignored): every writer notices, exits 3 naming its output, and the old output stays.
#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

class FullDisk : public WithSmallDataset {
 protected:
  // Runs with writes limited to `bytes` per file; `output` held "old" before and must still.
  void expect_old_output_kept(const std::vector<std::string>& args, const fs::path& output, unsigned long long bytes) {
    write_file(output, "old");
    Limits limits;
    limits.file_size_bytes = bytes;
    EXPECT_TRUE(exits_with_one_line(run_cli(args, limits), 3, output.string()));
    EXPECT_EQ(read_file(output), "old");
    EXPECT_TRUE(leftovers(dir()).empty());
  }
};

TEST_F(FullDisk, JsonWriterKeepsTheOldFile) {
  const fs::path json = dir() / "result.json";
  expect_old_output_kept({"detect", ds(), "-q", "--json", json.string()}, json, 1024);
}

TEST_F(FullDisk, PdfReportKeepsTheOldFile) {
  // The report is ~140 KB; its map image and PLY stay below the limit.
  const fs::path pdf = dir() / "report.pdf";
  expect_old_output_kept({"map", ds(), "-q", "--report", pdf.string()}, pdf, 20 * 1024);
}

TEST_F(FullDisk, LabelImageKeepsTheOldFile) {
  const fs::path labels = dir() / "labels.png";
  expect_old_output_kept({"planes", ds() + "/depth/000000.png", "--labels", labels.string()}, labels, 1024);
}

}  // namespace
}  // namespace tunnelmap::hostile
