#include "tests/hostile/hostile_checks.h"

#include <fstream>
#include <random>
#include <sstream>

#include "tests/support/io_temp_dir.h"

namespace tunnelmap::hostile {

namespace fs = std::filesystem;

::testing::AssertionResult exits_with_one_line(const Outcome& o, int code, const std::string& names) {
  auto failure = [&] {
    return ::testing::AssertionFailure() << "exit " << o.exit_code << ", signal " << o.term_signal
                                         << (o.timed_out ? ", timed out" : "") << "; stderr: " << o.err;
  };
  if (o.timed_out || o.term_signal || o.exit_code != code) return failure() << " (expected exit " << code << ")";
  const auto lines = std::count(o.err.begin(), o.err.end(), '\n');
  if (lines != 1) return failure() << " (expected exactly one line)";
  if (o.err.find(names) == std::string::npos) return failure() << " (expected it to name " << names << ")";
  return ::testing::AssertionSuccess();
}

std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.find(".tmp-") != std::string::npos || name.find(".old-") != std::string::npos)
      found.push_back(it->path().string());
  }
  return found;
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

void copy_small_dataset(const fs::path& to) {
  static testing::IoTempDir made;  // lives until the test binary exits
  static const fs::path source = [] {
    const fs::path ds = made.path() / "ds";
    const Outcome o = run_cli({"simulate", ds.string(), "--frames", "3", "--quiet"});
    if (o.exit_code != 0) throw std::runtime_error("simulate failed: " + o.err);
    return ds;
  }();
  fs::copy(source, to, fs::copy_options::recursive);
}

WithSmallDataset::WithSmallDataset() {
  dir_ = fs::temp_directory_path() / ("tunnelmap-hostile-" + std::to_string(std::random_device()()));
  fs::create_directories(dir_);
  copy_small_dataset(dir_ / "ds");
}

WithSmallDataset::~WithSmallDataset() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

const fs::path& WithSmallDataset::dir() const { return dir_; }

void WithSmallDataset::edit_index(const std::function<void(nlohmann::json&)>& change) const {
  nlohmann::json j = nlohmann::json::parse(read_file(index()));
  change(j);
  write_file(index(), j.dump());
}

}  // namespace tunnelmap::hostile
