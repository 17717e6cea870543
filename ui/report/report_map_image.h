#pragma once
// The 3D image of a map for the inspection report. tunnelmap-render draws it as a child process:
// its OSMesa shims must own their process's GL symbols, so neither tunnelmap-cli nor the GUI
// renders the report's image itself.
#include <string>

namespace tunnelmap {

// Renders the map mesh `map_ply` to `png` (oblique view) with the tunnelmap-render beside this
// executable (or in the build tree's render/ folder). False, with a one-line reason in `why_not`, when the renderer is missing or fails.
bool render_map_image(const std::string& map_ply, const std::string& png, std::string& why_not);

// The same with an explicit renderer executable.
bool render_map_image_with(const std::string& renderer, const std::string& map_ply, const std::string& png,
                           std::string& why_not);

}  // namespace tunnelmap
