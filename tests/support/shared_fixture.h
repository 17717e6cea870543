#pragma once
// Products of an expensive test fixture (a simulated dataset, the outputs of a CLI run) made once
// per build and reused by every test process that needs them. gtest_discover_tests runs each
// TEST in a process of its own, so a suite's SetUpTestSuite would otherwise redo its work once
// per test.
//
// A fixture lives in ROOT/NAME/HASH, HASH being that of its fingerprint (what made it: command
// lines, the binaries' size and time). It is made under an exclusive flock on ROOT/NAME.lock, so
// processes running in parallel wait for the first one instead of making it again, into a
// temporary folder renamed into place only when the maker succeeded: a folder at its final path
// is always complete, and a failed make is never kept. Tests read the folder and write their own
// outputs elsewhere (their own IoTempDir).
#include <filesystem>
#include <functional>
#include <string>

namespace tunnelmap::testing {

// Makes the products in `dir` (new and empty); returns "" on success, else what failed.
using FixtureMaker = std::function<std::string(const std::filesystem::path& dir)>;

struct SharedFixture {
  std::filesystem::path dir;  // the products (empty when the make failed): read, never write
  std::string error;          // what failed, empty when the products are there
  bool reused = false;        // made by an earlier call (this process or another)

  bool ok() const { return error.empty(); }
  std::string file(const std::string& name) const { return (dir / name).string(); }
};

// The fixture NAME (unique within `root`) made by `make` with `fingerprint`: reused if one with
// the same fingerprint was made before, else made now. Fixtures of NAME with another
// fingerprint are removed. A maker's exception counts as its failure.
SharedFixture shared_fixture_in(const std::filesystem::path& root, const std::string& name,
                                const std::string& fingerprint, const FixtureMaker& make);

// The same under this build's fixture folder (build_paths::test_fixture_dir()).
SharedFixture shared_fixture(const std::string& name, const std::string& fingerprint,
                             const FixtureMaker& make);

// "PATH SIZE MTIME_NS" of a file, for fingerprints: a rebuilt binary makes its fixtures anew.
std::string file_stamp(const std::filesystem::path& path);

// The stamp of the running test program (the simulator and helpers are linked into it).
std::string test_binary_stamp();

}  // namespace tunnelmap::testing
