#pragma once
// An empty folder under the test temp dir, named `name` (removed and made again).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tunnelmap {

inline std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace tunnelmap
