// `tunnelmap-cli render ...`: headless screenshots through OSMesa. The OSMesa GL shims must
// own the process's gl* symbols, so rendering lives in its own executable (tunnelmap-render,
// see docs/gui.md); this verb hands the arguments over to it unchanged.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <iostream>
#include <vector>

#include "app/cli/commands.h"
#include "core/util/renderer_path.h"

namespace tunnelmap::cli {

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
