#include "core/util/renderer_path.h"

#include <cstdlib>

namespace tunnelmap {

std::filesystem::path find_renderer() {
  if (const char* chosen = std::getenv("TUNNELMAP_RENDER"); chosen && *chosen) return chosen;
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = ec ? std::filesystem::path(".") : self.parent_path();
  for (const auto& candidate :
       {dir / "tunnelmap-render", dir / "render" / "tunnelmap-render", dir.parent_path() / "render" / "tunnelmap-render"})
    if (std::filesystem::exists(candidate)) return candidate;
  return dir / "tunnelmap-render";
}

}  // namespace tunnelmap
