#pragma once
// Whether a (resolved, absolute) path lies inside a folder: the path rules of dataset folders
// and TUM sequences (no frame may escape its folder, symlinks included).
#include <filesystem>

namespace tunnelmap {

inline bool path_is_inside(const std::filesystem::path& root, const std::filesystem::path& p) {
  auto r = root.begin(), q = p.begin();
  for (; r != root.end(); ++r, ++q) {
    if (r->empty()) continue;  // trailing separator
    if (q == p.end() || *r != *q) return false;
  }
  return true;
}

}  // namespace tunnelmap
