#pragma once
// This process's memory as /proc/self/status reports it.
#include <cstdlib>
#include <fstream>
#include <string>

namespace tunnelmap::testing {

// A "Vm…" field of /proc/self/status in MB, e.g. "VmRSS" (resident) or "VmHWM" (peak); -1 if
// it is missing.
inline double status_mb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(key) + ":";
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) return std::atof(line.c_str() + prefix.size()) / 1024.0;  // kB
  return -1.0;
}

}  // namespace tunnelmap::testing
