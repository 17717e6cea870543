#pragma once
// Where tunnelmap-render is: beside tunnelmap-cli and tunnelmap when installed (all in bin/);
// in the build tree in app/render/, beside app/tunnelmap-cli and app/gui/tunnelmap.
#include <filesystem>

namespace tunnelmap {

// $TUNNELMAP_RENDER when set; else the first candidate that exists; otherwise the installed
// location (for the error message).
std::filesystem::path find_renderer();

}  // namespace tunnelmap
