#pragma once
// Shared by the fuzz targets: a per-process scratch folder for readers that need a path.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace tunnelmap::fuzz {

// <base>/tunnelmap-fuzz-<name>-<pid>, created once, removed at a normal exit.
inline const std::filesystem::path& scratch_dir(const std::string& name) {
  static const std::filesystem::path dir = [&] {
    // $TUNNELMAP_FUZZ_SCRATCH (scripts/fuzz.sh: in the build dir, removed even after a crash),
    // else RAM-backed when possible: the PCD and preset targets write every input to a file.
    std::error_code ec;
    const char* given = std::getenv("TUNNELMAP_FUZZ_SCRATCH");
    const std::filesystem::path base = given && *given ? std::filesystem::path(given)
                                       : std::filesystem::is_directory("/dev/shm", ec)
                                           ? std::filesystem::path("/dev/shm")
                                           : std::filesystem::temp_directory_path();
    std::filesystem::path d = base / ("tunnelmap-fuzz-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    static const std::filesystem::path to_remove = d;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(to_remove, ec);
    });
    return d;
  }();
  return dir;
}

inline void write_bytes(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace tunnelmap::fuzz
