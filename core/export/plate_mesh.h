#pragma once
// The plates across a girder (diaphragms) as surfaces for the map mesh: each plate's
// cross-section rectangle with its manhole opening cut out, triangulated in the world frame.
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

struct PlateOpening {
  double lateral_m = 0.0, vertical_m = 0.0;  // centre, from the plate's centre (left, up)
  double width_m = 0.0, height_m = 0.0;
  std::string shape;  // "ellipse" or "rounded_rectangle"
  double corner_radius_m = 0.0;
};

struct PlateOutline {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // world: the centre line at the plate
  Eigen::Vector3d left = Eigen::Vector3d::UnitY(), up = Eigen::Vector3d::UnitZ();  // in its plane
  double width_m = 0.0, height_m = 0.0;  // the cross-section measured there
  std::optional<PlateOpening> opening;   // none: no manhole was measured
};

// The map's diaphragms whose cross-section was measured at (or next to) their station; a plate
// whose width or height no station measured is left out (nothing is drawn from a design).
std::vector<PlateOutline> plate_outlines(const StationMap& map);

struct PlateMesh {
  std::vector<Eigen::Vector3d> vertices;        // world frame
  std::vector<std::array<int, 3>> triangles;
};

// The plate's rectangle less its opening: a ring of quads from the opening's outline (sampled
// every 360/`samples` degrees around its centre, plus the rectangle's corners) out to the
// rectangle. Without an opening, two triangles.
PlateMesh triangulate_plate(const PlateOutline& plate, int samples = 72);

}  // namespace tunnelmap
