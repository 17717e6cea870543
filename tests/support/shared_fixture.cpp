#include "tests/support/shared_fixture.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/util/build_paths.h"
#include "tests/support/exclusive_file_lock.h"

namespace tunnelmap::testing {

namespace fs = std::filesystem;

namespace {

// Written into a fixture last, before the rename: its whole fingerprint (the folder name holds
// only a hash of it, and a collision must not pass for a match).
const char* const kFingerprintFile = ".fingerprint";
const char* const kTempPrefix = ".tmp-";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// FNV-1a, 64 bits: the same in every process and compiler, unlike std::hash.
std::string hash_hex(const std::string& text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

bool is_temp(const fs::path& entry) { return entry.filename().string().rfind(kTempPrefix, 0) == 0; }

// A temporary folder whose maker died mid-way (its process no longer runs): never renamed into
// place, so never read, only removed. Another live process's one is left alone.
bool abandoned(const fs::path& entry) {
  const long pid = std::strtol(entry.filename().string().c_str() + std::strlen(kTempPrefix), nullptr, 10);
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Before a new make: the fixtures of this name made with other fingerprints (older binaries)
// and abandoned temporary folders go, so the build tree does not grow with every rebuild.
void remove_stale(const fs::path& name_dir) {
  for (const fs::directory_entry& e : fs::directory_iterator(name_dir)) {
    if (is_temp(e.path()) && !abandoned(e.path())) continue;
    std::error_code ec;
    fs::remove_all(e.path(), ec);
  }
}

fs::path new_temp_dir(const fs::path& name_dir) {
  static std::atomic<int> counter{0};
  const fs::path dir = name_dir / (kTempPrefix + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string run_maker(const FixtureMaker& make, const fs::path& dir) {
  try {
    return make(dir);
  } catch (const std::exception& e) {
    return std::string("the fixture's maker threw: ") + e.what();
  } catch (...) {
    return "the fixture's maker threw";
  }
}

// Makes the fixture in a temporary folder and renames it to `final_dir` only if it succeeded.
std::string make_in_place(const fs::path& name_dir, const fs::path& final_dir, const std::string& fingerprint,
                          const FixtureMaker& make) {
  const fs::path tmp = new_temp_dir(name_dir);
  std::string error = run_maker(make, tmp);
  if (error.empty()) {
    std::ofstream(tmp / kFingerprintFile, std::ios::binary) << fingerprint;
    if (read_text(tmp / kFingerprintFile) != fingerprint) error = "cannot write " + (tmp / kFingerprintFile).string();
  }
  std::error_code ec;
  if (error.empty()) fs::rename(tmp, final_dir, ec);
  if (error.empty() && ec) error = "cannot rename " + tmp.string() + " to " + final_dir.string() + ": " + ec.message();
  if (!error.empty()) fs::remove_all(tmp, ec);
  return error;
}

}  // namespace

SharedFixture shared_fixture_in(const fs::path& root, const std::string& name, const std::string& fingerprint,
                                const FixtureMaker& make) {
  const fs::path name_dir = root / name;
  fs::create_directories(name_dir);
  // Held while checking and making: a second process waits here, then finds the fixture made.
  const ExclusiveFileLock lock(root / (name + ".lock"));
  const fs::path final_dir = name_dir / hash_hex(fingerprint);
  SharedFixture f;
  if (read_text(final_dir / kFingerprintFile) == fingerprint) {
    f.dir = final_dir;
    f.reused = true;
    return f;
  }
  remove_stale(name_dir);
  f.error = make_in_place(name_dir, final_dir, fingerprint, make);
  if (f.ok()) f.dir = final_dir;
  return f;
}

SharedFixture shared_fixture(const std::string& name, const std::string& fingerprint, const FixtureMaker& make) {
  return shared_fixture_in(build_paths::test_fixture_dir(), name, fingerprint, make);
}

std::string file_stamp(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return path.string() + " missing";
  return path.string() + " " + std::to_string(st.st_size) + " " +
         std::to_string(static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec);
}

std::string test_binary_stamp() { return file_stamp(fs::read_symlink("/proc/self/exe")); }

}  // namespace tunnelmap::testing
