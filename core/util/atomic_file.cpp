#include "core/util/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "core/util/error.h"
#include "core/util/sibling_name.h"
#include "core/util/temp_registry.h"

namespace tunnelmap {
namespace fs = std::filesystem;

namespace {
std::string temporary_name(const std::string& path) {
  // Not scratch but a random source: one engine per thread because threads writing outputs at
  // once must not share (race on) one engine, and each is seeded from random_device so their
  // temporary names differ; a local engine would read random_device on every file.
  static thread_local std::mt19937_64 rng{std::random_device{}()};
  return sibling_name(path, "", ".tmp-" + std::to_string(rng() % 1000000), true).string();
}
}  // namespace

void write_path_atomically(const std::string& path,
                           const std::function<void(const std::string&)>& write) {
  check_output_path(path);
  const std::string target = output_target(path).string();
  const std::string tmp = temporary_name(target);  // beside the target: rename stays atomic
  try {
    TempRegistry::create(tmp, [&] { write(tmp); });
    if (!fs::exists(tmp)) throw InputError(path, "cannot write: the writer produced no file");
    std::error_code ec;
    TempRegistry::publish(tmp, [&] {
      fs::rename(tmp, target, ec);
      return !ec;
    });
    if (ec) throw InputError(path, "cannot write: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    TempRegistry::remove(tmp);
    throw;
  }
}

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  write_path_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "cannot write: cannot create a file in that folder");
    write(out);
    out.flush();
    out.close();  // the last buffered bytes can fail here too (disk full, file size limit)
    if (!out) throw InputError(path, "cannot write: write error (disk full?)");
  });
}

}  // namespace tunnelmap
