#pragma once
// What every hostile case asserts: the exit status, exactly one stderr line naming the file,
// no temporary file or folder left behind, old outputs intact.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/hostile/cli_process.h"

namespace tunnelmap::hostile {

// Exit status `code` (not a signal, not a timeout) and one stderr line that contains `names`.
::testing::AssertionResult exits_with_one_line(const Outcome& o, int code, const std::string& names);

// Files and folders under `dir` (recursively) that a run leaves only when it failed to clean
// up: temporary outputs "*.tmp-*" and replaced folders "*.old-*".
std::vector<std::string> leftovers(const std::filesystem::path& dir);

std::string read_file(const std::filesystem::path& p);
void write_file(const std::filesystem::path& p, const std::string& bytes);

// A small simulated dataset (3 lab frames), made once per test binary by the real CLI and
// copied for each test so that no test can spoil another's input.
void copy_small_dataset(const std::filesystem::path& to);

// A test with its own temporary folder holding a copy of the small dataset ("ds").
class WithSmallDataset : public ::testing::Test {
 protected:
  WithSmallDataset();
  ~WithSmallDataset() override;
  const std::filesystem::path& dir() const;
  std::string ds() const { return (dir() / "ds").string(); }
  std::filesystem::path index() const { return dir() / "ds" / "dataset.json"; }
  // Rewrites the dataset's index after `change`.
  void edit_index(const std::function<void(nlohmann::json&)>& change) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace tunnelmap::hostile
