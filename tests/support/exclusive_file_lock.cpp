#include "tests/support/exclusive_file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tunnelmap::testing {

ExclusiveFileLock::ExclusiveFileLock(const std::filesystem::path& file)
    : fd_(::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644)) {
  if (fd_ < 0) throw std::runtime_error("cannot open " + file.string() + ": " + std::strerror(errno));
  while (::flock(fd_, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    const int e = errno;
    ::close(fd_);
    throw std::runtime_error("cannot lock " + file.string() + ": " + std::strerror(e));
  }
}

ExclusiveFileLock::~ExclusiveFileLock() { ::close(fd_); }  // closing releases the lock

}  // namespace tunnelmap::testing
