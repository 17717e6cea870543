// `tunnelmap-cli render ...`: headless screenshots through OSMesa. The OSMesa GL shims must
// own the process's gl* symbols, so rendering lives in its own executable (tunnelmap-render,
// see docs/gui.md); this verb hands the arguments over to it unchanged.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

#include "app/cli/commands.h"

namespace tunnelmap::cli {

namespace {
std::filesystem::path find_renderer() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = ec ? std::filesystem::path(".") : self.parent_path();
  for (const auto& candidate : {dir / "tunnelmap-render", dir / "render" / "tunnelmap-render"})
    if (std::filesystem::exists(candidate)) return candidate;
  return dir / "tunnelmap-render";
}
}  // namespace

int run_render_verb(int argc, char** argv) {
  const std::string renderer = find_renderer().string();
  std::vector<char*> args;
  args.push_back(const_cast<char*>("tunnelmap-render"));
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  execv(renderer.c_str(), args.data());
  std::cerr << "tunnelmap-cli: cannot run " << renderer << ": " << std::strerror(errno)
            << " (built with -DTUNNELMAP_BUILD_GUI=ON?)\n";
  return 4;
}

}  // namespace tunnelmap::cli
