#pragma once
// Standard camera views of the tunnel: along its axis, from the side, from above, reset, and an
// oblique 3/4 view from above one side (the whole map at a glance, e.g. a map mesh).
#include <string>

#include <vtkRenderer.h>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

enum class ViewPreset { Along, Side, Top, Reset, Oblique };

const char* view_name(ViewPreset v);  // "along", "side", "top", "reset", "oblique"
// Throws std::invalid_argument for an unknown name.
ViewPreset parse_view(const std::string& name);

// Points the renderer's camera for `view` and fits the visible props. Uses the tunnel axis and
// "up" when the map is detected, else the camera frame (z forward, -y up).
void apply_view(vtkRenderer* renderer, ViewPreset view, const TunnelMap& map);

// Keeps the camera's direction, centres the map's tunnel box (the visible props' bounds when
// no map is detected) and zooms until it fills ~90 % of the view. ResetCamera fits a bounding
// sphere, which leaves a long tunnel small in the middle; the oblique view always fits this way.
// Needs the renderer in a render window (for the aspect ratio).
void fit_view_to_map(vtkRenderer* renderer, const TunnelMap& map);

}  // namespace tunnelmap::scene
