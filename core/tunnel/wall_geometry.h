#pragma once
// Step 6 of tunnel detection: the map geometry. Given the template frame and the four wall
// offsets, the centre line, each wall's rectangle over the visible extent and its zones
// (forbidden riveted bands along the tunnel corners, traversable middle plate).
#include <Eigen/Core>
#include <array>

#include "core/tunnel/template_fit.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct WallOffsets {
  double left = 0, right = 0, top = 0, bottom = 0;  // plane offsets (camera frame, > 0)
};

// Fills map.axis_point/axis_dir/up, extent_min_m/extent_max_m and for each wall normal,
// offset_m, boundary and zones. `axial_min`/`axial_max`: min/max of axis . p over the visible
// wall points (camera frame, absolute).
void build_wall_geometry(const TemplateFrame& frame, const WallOffsets& offsets, double axial_min,
                         double axial_max, double forbidden_band_m, TunnelMap& map);

// build_wall_geometry again from what the map holds (its frame, extent and every wall's
// offset_m), after a wall was inferred. Walls that are not found get no zones.
void rebuild_wall_geometry(TunnelMap& map, double forbidden_band_m);

// A rectangle on a wall: `edge_a`/`edge_b` are the wall's two cross-section end points (at
// axial position 0), `n` the wall's inward normal. Corners are counter-clockwise seen from
// inside the tunnel (their right-hand normal is +n), starting at the lower across-coordinate
// edge, at t0. `from`/`to` select a band of the across span, in metres from the low edge.
std::array<Eigen::Vector3d, 4> wall_rectangle(const Eigen::Vector3d& n, const Eigen::Vector3d& axis,
                                              const Eigen::Vector3d& edge_a,
                                              const Eigen::Vector3d& edge_b, double t0, double t1,
                                              double from, double to);

}  // namespace tunnelmap
