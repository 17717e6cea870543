// A real .oni recording (made by `tunnelmap-cli record` from the simulated camera) with single
// bytes changed: OpenNI2's player crashes or hangs on such files, so the recording is checked
// before it opens them. Every variant must end in exit 0 or one line naming the file.
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/util/build_paths.h"
#include "tests/hostile/hostile_checks.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/oni_variants.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;

// Two frames of depth and colour, recorded once per test binary.
const std::string& recording() {
  static testing::IoTempDir made;
  static const std::string bytes = [] {
    const fs::path oni = made.path() / "lab.oni";
    const Outcome o = run_cli({"record", "--device", "tunnelmap-sim://lab?pose=0&frames=2&fps=0", "--frames", "2", oni.string()},
                              {}, {}, {"LD_LIBRARY_PATH=" + std::string(TUNNELMAP_OPENNI2_RUNTIME_DIR)});
    if (o.exit_code != 0) throw std::runtime_error("record failed: " + o.err);
    return read_file(oni);
  }();
  return bytes;
}

class OniRecordings : public ::testing::Test {
 protected:
  testing::IoTempDir tmp_;
  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = tmp_.file(name);
    write_file(path, bytes);
    return path;
  }
  // Runs detect on `path` with a JSON output over an old one; checks the outcome is exit 0
  // (old output replaced) or one line naming the file (old output kept), and no leftovers.
  void expect_clean_outcome(const std::string& path, const std::string& what) {
    const fs::path json = tmp_.path() / "out.json";
    write_file(json, "old");
    const Outcome o = run_cli({"detect", path, "-q", "--json", json.string()});
    if (o.exit_code == 0 && !o.timed_out && o.term_signal == 0) {
      EXPECT_EQ(o.err, "") << what;
    } else {
      EXPECT_TRUE(exits_with_one_line(o, 3, path)) << what;
      EXPECT_EQ(read_file(json), "old") << what;
    }
    EXPECT_TRUE(leftovers(tmp_.path()).empty()) << what;
  }
  // One of 8 shards of the 200 single-byte changes (separate tests so they run in parallel).
  void sweep(std::size_t shard) {
    const std::string& good = recording();
    const std::vector<std::size_t> at = testing::oni_change_positions(good);
    ASSERT_EQ(at.size(), 200u);
    for (std::size_t k = shard; k < at.size(); k += 8) {
      const std::string bytes = testing::oni_changed(good, at[k], k);
      expect_clean_outcome(write("changed.oni", bytes), "byte " + std::to_string(at[k]) + " set to " +
                                                            std::to_string(static_cast<unsigned char>(bytes[at[k]])));
    }
  }
};

TEST_F(OniRecordings, TheUnchangedRecordingPlaysBack) {
  const Outcome o = run_cli({"detect", write("lab.oni", recording()), "-q"});
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("summary: 2/2 frames detected"), std::string::npos) << o.out;
}

// The changes that crashed OpenNI's player in a recording of the same layout.
TEST_F(OniRecordings, AChangedPropertyRecordIsOneLine) {
  std::string b = recording();
  b[363] = static_cast<char>(0x80);
  const std::string path = write("byte363.oni", b);
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", path, "-q"}), 3, path));
  b = recording();
  for (std::size_t i = 544; i <= 547; ++i) b[i] = static_cast<char>(0xFF);
  const std::string path2 = write("bytes544.oni", b);
  EXPECT_TRUE(exits_with_one_line(run_cli({"detect", path2, "-q"}), 3, path2));
}

TEST_F(OniRecordings, ATruncatedRecordingIsOneLine) {
  const std::string path = write("cut.oni", recording().substr(0, recording().size() / 4));
  const Outcome o = run_cli({"detect", path, "-q"});
  EXPECT_TRUE(exits_with_one_line(o, 3, path));
  EXPECT_NE(o.err.find("truncated"), std::string::npos) << o.err;
}

TEST_F(OniRecordings, SingleByteChanges0) { sweep(0); }
TEST_F(OniRecordings, SingleByteChanges1) { sweep(1); }
TEST_F(OniRecordings, SingleByteChanges2) { sweep(2); }
TEST_F(OniRecordings, SingleByteChanges3) { sweep(3); }
TEST_F(OniRecordings, SingleByteChanges4) { sweep(4); }
TEST_F(OniRecordings, SingleByteChanges5) { sweep(5); }
TEST_F(OniRecordings, SingleByteChanges6) { sweep(6); }
TEST_F(OniRecordings, SingleByteChanges7) { sweep(7); }

}  // namespace
}  // namespace tunnelmap::hostile
