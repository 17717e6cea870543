#include "ui/scene/scene_colors.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap::scene {

Rgb wall_class_color(WallClass c) {
  switch (c) {
    case WallClass::Left: return {0.30, 0.78, 0.30};
    case WallClass::Right: return {0.95, 0.50, 0.80};
    case WallClass::Top: return {0.62, 0.45, 0.90};
    case WallClass::Bottom: return {0.55, 0.85, 1.00};  // pale sky: apart from "left" green for deuteranopes
    case WallClass::Unassigned: break;
  }
  return {0.60, 0.60, 0.60};
}

const char* wall_class_label(WallClass c) {
  switch (c) {
    case WallClass::Left: return "left";
    case WallClass::Right: return "right";
    case WallClass::Top: return "top";
    case WallClass::Bottom: return "bottom";
    case WallClass::Unassigned: break;
  }
  return "unassigned";
}

Rgb depth_color(double t) {
  // Five control points of viridis; linear in between.
  static const Rgb stops[] = {{0.267, 0.005, 0.329},
                              {0.231, 0.322, 0.545},
                              {0.129, 0.569, 0.549},
                              {0.369, 0.788, 0.384},
                              {0.992, 0.906, 0.145}};
  if (!(t == t)) t = 0.0;
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(std::floor(t)));
  const double f = t - i;
  Rgb out;
  for (int k = 0; k < 3; ++k) out[k] = stops[i][k] * (1.0 - f) + stops[i + 1][k] * f;
  return out;
}

}  // namespace tunnelmap::scene
