#pragma once
// Standard camera views of the tunnel: along its axis, from the side, from above, reset.
#include <string>

#include <vtkRenderer.h>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

enum class ViewPreset { Along, Side, Top, Reset };

const char* view_name(ViewPreset v);  // "along", "side", "top", "reset"
// Throws std::invalid_argument for an unknown name.
ViewPreset parse_view(const std::string& name);

// Points the renderer's camera for `view` and fits the visible props. Uses the tunnel axis and
// "up" when the map is detected, else the camera frame (z forward, -y up).
void apply_view(vtkRenderer* renderer, ViewPreset view, const TunnelMap& map);

}  // namespace tunnelmap::scene
