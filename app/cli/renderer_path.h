#pragma once
// Where tunnelmap-render is: beside tunnelmap-cli when installed (both in bin/), in render/
// beside it in the build tree (app/tunnelmap-cli, app/render/tunnelmap-render).
#include <filesystem>

namespace tunnelmap::cli {

// The first candidate that exists; otherwise the installed location (for the error message).
std::filesystem::path find_renderer();

}  // namespace tunnelmap::cli
