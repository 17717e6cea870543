#pragma once
// An exclusive flock held for the object's lifetime. The kernel drops it when the process dies,
// so a crashed holder never leaves others waiting. Two objects conflict even within one process
// (each opens the file anew).
#include <filesystem>

namespace tunnelmap::testing {

class ExclusiveFileLock {
 public:
  explicit ExclusiveFileLock(const std::filesystem::path& file);  // blocks until held
  ~ExclusiveFileLock();
  ExclusiveFileLock(const ExclusiveFileLock&) = delete;
  ExclusiveFileLock& operator=(const ExclusiveFileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace tunnelmap::testing
