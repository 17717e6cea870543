#pragma once
// The third-party recordings (../shared/data/recordings beside the checkout; see its
// SOURCES.md). Tests that read them skip when the folder is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include "core/util/build_paths.h"

namespace tunnelmap::testing {

inline std::filesystem::path recordings_dir() {
  return std::filesystem::path(TUNNELMAP_SOURCE_DIR) / ".." / "shared" / "data" / "recordings";
}

inline std::string recording(const std::string& relative) { return (recordings_dir() / relative).string(); }

}  // namespace tunnelmap::testing

#define SKIP_WITHOUT_RECORDINGS()                                                                   \
  do {                                                                                              \
    if (!std::filesystem::is_directory(::tunnelmap::testing::recordings_dir()))                     \
      GTEST_SKIP() << "third-party recordings not found at " << ::tunnelmap::testing::recordings_dir(); \
  } while (0)
