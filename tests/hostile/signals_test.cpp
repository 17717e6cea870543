// SIGINT and SIGTERM while a command works: the run stops, every temporary file and folder it
// made is removed, outputs from before are kept, one line, exit 130 (INT) or 143 (TERM).
#include <signal.h>

#include <nlohmann/json.hpp>
#include <optional>

#include "tests/hostile/hostile_checks.h"
#include "tests/support/io_temp_dir.h"

namespace tunnelmap::hostile {
namespace {

namespace fs = std::filesystem;
using clock_type = std::chrono::steady_clock;

// The small dataset with its 3 frames listed `n` times over: long enough to interrupt.
fs::path long_dataset(const fs::path& dir, int n) {
  const fs::path ds = dir / "long";
  copy_small_dataset(ds);
  nlohmann::json j = nlohmann::json::parse(read_file(ds / "dataset.json"));
  const nlohmann::json three = j["frames"];
  j["frames"] = nlohmann::json::array();
  for (int i = 0; i < n; ++i) {
    j["frames"].push_back(three[i % three.size()]);
    j["frames"].back()["timestamp"] = i / 30.0;  // increasing, as a reader expects
  }
  write_file(ds / "dataset.json", j.dump());
  fs::remove(ds / ".tunnelmap-written");
  return ds;
}

// Signals once a temporary output appears under `dir`, or `at_most` after the program began.
Limits signal_during_write(int signal, const fs::path& dir, std::chrono::milliseconds at_most) {
  Limits l;
  l.signal = signal;
  l.signal_when = [dir, at_most, start = std::optional<clock_type::time_point>()]() mutable {
    if (!start) start = clock_type::now();
    return !leftovers(dir).empty() || clock_type::now() - *start > at_most;
  };
  return l;
}

// Signals only once the staged output folder (a temporary under `dir`) exists: the signal then
// always lands while the folder is half written, however slow the machine. The commands given
// to it write for tens of seconds after the folder appears (simulate: 200 frames, about 40 s),
// far beyond the poll's few milliseconds.
Limits signal_while_staged(int signal, const fs::path& dir) {
  Limits l;
  l.signal = signal;
  l.signal_when = [dir] { return !leftovers(dir).empty(); };
  return l;
}

class Signals : public ::testing::Test {
 protected:
  fs::path dir() const { return tmp_.path(); }
  fs::path out() const { return tmp_.path() / "out"; }
  void SetUp() override { fs::create_directories(out()); }

  void expect_clean_stop(const Outcome& o, int signal) {
    ASSERT_TRUE(o.signal_sent) << "finished before the signal: " << o.err;
    EXPECT_TRUE(exits_with_one_line(o, 128 + signal, signal == SIGINT ? "SIGINT" : "SIGTERM"));
    EXPECT_TRUE(leftovers(dir()).empty()) << leftovers(dir()).front();
  }

  // `args` followed by `output`, which held "old" before the signal and must still.
  void expect_old_output_kept(std::vector<std::string> args, const fs::path& output, int signal) {
    write_file(output, "old");
    args.push_back(output.string());
    expect_clean_stop(run_cli(args, signal_during_write(signal, out(), std::chrono::milliseconds(1500))), signal);
    EXPECT_EQ(read_file(output), "old");
  }

 private:
  testing::IoTempDir tmp_;
};

TEST_F(Signals, SimulateInterruptedKeepsNoHalfFolder) {
  const fs::path ds = out() / "sim";
  const Outcome o = run_cli({"simulate", ds.string(), "--frames", "200", "--quiet"}, signal_while_staged(SIGINT, out()));
  expect_clean_stop(o, SIGINT);
  EXPECT_FALSE(fs::exists(ds));
}

TEST_F(Signals, ConvertTerminatedKeepsNoHalfFolder) {
  const fs::path ds = long_dataset(dir(), 300), tum = out() / "tum";
  const Outcome o = run_cli({"convert", ds.string(), tum.string(), "--to", "tum", "-q"},
                            signal_during_write(SIGTERM, out(), std::chrono::milliseconds(800)));
  expect_clean_stop(o, SIGTERM);
  EXPECT_FALSE(fs::exists(tum));
}

TEST_F(Signals, FuseInterruptedKeepsTheOldMesh) {
  const fs::path ds = long_dataset(dir(), 60);
  expect_old_output_kept({"fuse", ds.string(), "--quiet", "--mesh"}, out() / "mesh.ply", SIGINT);
}

TEST_F(Signals, MapReportTerminatedKeepsTheOldReport) {
  const fs::path ds = long_dataset(dir(), 60);
  expect_old_output_kept({"map", ds.string(), "-q", "--report"}, out() / "report.pdf", SIGTERM);
}

}  // namespace
}  // namespace tunnelmap::hostile
