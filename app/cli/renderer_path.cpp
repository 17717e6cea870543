#include "app/cli/renderer_path.h"

namespace tunnelmap::cli {

std::filesystem::path find_renderer() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = ec ? std::filesystem::path(".") : self.parent_path();
  for (const auto& candidate : {dir / "tunnelmap-render", dir / "render" / "tunnelmap-render"})
    if (std::filesystem::exists(candidate)) return candidate;
  return dir / "tunnelmap-render";
}

}  // namespace tunnelmap::cli
