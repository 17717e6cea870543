// TUM RGB-D lists as other editors save them: a UTF-8 byte order mark first, and line ends of
// a lone CR (classic Mac) or CR LF (Windows). They mean the same list, so the run gives the
// same result as with plain LF lines.
#include "tests/hostile/hostile_checks.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
  return s;
}

std::string summary_without_time(const Outcome& o) {
  const std::string s = o.out.substr(o.out.rfind("summary:"));
  return s.substr(0, s.find(", median"));
}

using TextLists = WithSmallDataset;

TEST_F(TextLists, AByteOrderMarkAndCrLineEndsReadAsPlainLines) {
  const fs::path tum = dir() / "tum";
  ASSERT_EQ(run_cli({"convert", ds(), tum.string(), "--to", "tum", "-q"}).exit_code, 0);
  const Outcome plain = run_cli({"detect", tum.string(), "-q"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;

  const std::string bom = "\xEF\xBB\xBF";
  write_file(tum / "depth.txt", bom + replace_all(read_file(tum / "depth.txt"), "\n", "\r"));
  write_file(tum / "groundtruth.txt", bom + replace_all(read_file(tum / "groundtruth.txt"), "\n", "\r\n"));
  const Outcome edited = run_cli({"detect", tum.string(), "-q"});
  ASSERT_EQ(edited.exit_code, 0) << edited.err;
  EXPECT_EQ(edited.err, "");
  EXPECT_NE(plain.out.find("summary: 3/3 frames"), std::string::npos) << plain.out;
  EXPECT_EQ(summary_without_time(edited), summary_without_time(plain));
}

}  // namespace
}  // namespace tunnelmap::hostile
