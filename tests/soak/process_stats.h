#pragma once
// What a long-running process must not accumulate, read from /proc (Linux only): resident memory
// and open file descriptors.
#include <dirent.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tunnelmap::soak {

// VmRSS of this process in kB (-1 when /proc is unreadable).
inline long resident_kb() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (f == nullptr) return -1;
  char line[256];
  long kb = -1;
  while (std::fgets(line, sizeof line, f) != nullptr)
    if (std::strncmp(line, "VmRSS:", 6) == 0) {
      kb = std::strtol(line + 6, nullptr, 10);
      break;
    }
  std::fclose(f);
  return kb;
}

// Entries of /proc/self/fd, not counting the descriptor that lists them (-1 when unreadable).
inline int open_fds() {
  DIR* d = opendir("/proc/self/fd");
  if (d == nullptr) return -1;
  int n = 0;
  while (const dirent* e = readdir(d))
    if (e->d_name[0] != '.') ++n;
  closedir(d);
  return n - 1;
}

}  // namespace tunnelmap::soak
