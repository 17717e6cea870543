#pragma once
// Colours of the 3D scene, shared by the GUI legend, the renderer and the screenshot tests.
// Boundary blue and traversable red are saturated and drawn unlit so tests can find them;
// nothing else in the scene (depth colour map, wall classes, axes) uses such colours.
#include <array>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

using Rgb = std::array<double, 3>;  // 0..1

constexpr Rgb kBoundaryBlue{0.0, 0.2, 1.0};
constexpr Rgb kTraversableRed{1.0, 0.08, 0.08};
constexpr Rgb kForbiddenAmber{1.0, 0.7, 0.0};
constexpr Rgb kFrustumGrey{0.85, 0.85, 0.85};
constexpr Rgb kGridGrey{0.72, 0.72, 0.72};
constexpr Rgb kLegendText{0.95, 0.95, 0.95};  // also the grid labels
constexpr Rgb kMeasureWhite{1.0, 1.0, 1.0};  // picks, the measured segment and its length (nothing else is pure white)
// Zone fills let the wall's points show through; their outlines are opaque.
constexpr double kZoneFillOpacity = 0.35;
constexpr Rgb kBackground{0.12, 0.12, 0.14};

Rgb wall_class_color(WallClass c);
const char* wall_class_label(WallClass c);  // "left", ... "unassigned"

// Perceptual depth colour map (viridis-like: purple, teal, green, yellow), t in [0, 1].
Rgb depth_color(double t);

}  // namespace tunnelmap::scene
