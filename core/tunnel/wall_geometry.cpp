#include "core/tunnel/wall_geometry.h"

#include <utility>

#include <Eigen/Geometry>

namespace tunnelmap {

std::array<Eigen::Vector3d, 4> wall_rectangle(const Eigen::Vector3d& n, const Eigen::Vector3d& axis,
                                              const Eigen::Vector3d& edge_a,
                                              const Eigen::Vector3d& edge_b, double t0, double t1,
                                              double from, double to) {
  // Across direction chosen so that axis x across = n: (along, across) is then CCW about n.
  const Eigen::Vector3d across = n.cross(axis);
  Eigen::Vector3d lo = edge_a, hi = edge_b;
  if (across.dot(hi - lo) < 0) std::swap(lo, hi);
  const Eigen::Vector3d p0 = lo + from * across;
  const Eigen::Vector3d p1 = lo + to * across;
  return {p0 + t0 * axis, p0 + t1 * axis, p1 + t1 * axis, p1 + t0 * axis};
}

void build_wall_geometry(const TemplateFrame& frame, const WallOffsets& off, double axial_min,
                         double axial_max, double band, TunnelMap& map) {
  const Eigen::Vector3d& r = frame.right;
  const Eigen::Vector3d& u = frame.up;
  const Eigen::Vector3d& ax = frame.axis;
  // Cross-section coordinates (r . x, u . x) of the four wall planes.
  const double r_left = -off.left, r_right = off.right;
  const double v_bottom = -off.bottom, v_top = off.top;
  auto at = [&](double rr, double vv) -> Eigen::Vector3d { return rr * r + vv * u; };

  map.axis_dir = ax;
  map.up = u;
  map.axis_point = at(0.5 * (r_left + r_right), 0.5 * (v_bottom + v_top)) + axial_min * ax;
  map.extent_min_m = 0.0;
  map.extent_max_m = axial_max - axial_min;

  struct Spec { WallClass cls; Eigen::Vector3d n; double offset; Eigen::Vector3d a, b; };
  const Spec specs[] = {
      {WallClass::Left, r, off.left, at(r_left, v_bottom), at(r_left, v_top)},
      {WallClass::Right, -r, off.right, at(r_right, v_bottom), at(r_right, v_top)},
      {WallClass::Top, -u, off.top, at(r_left, v_top), at(r_right, v_top)},
      {WallClass::Bottom, u, off.bottom, at(r_left, v_bottom), at(r_right, v_bottom)},
  };
  for (const auto& s : specs) {
    Wall& w = map.wall(s.cls);
    w.normal = s.n;
    w.offset_m = s.offset;
    const double span = (s.b - s.a).norm();
    w.boundary = wall_rectangle(s.n, ax, s.a, s.b, axial_min, axial_max, 0.0, span);
    w.zones.clear();
    if (span <= 2.0 * band) {
      // Too narrow for a middle plate: the whole wall is riveted edge.
      w.zones.push_back({ZoneKind::Forbidden, w.boundary});
      continue;
    }
    w.zones.push_back({ZoneKind::Forbidden,
                       wall_rectangle(s.n, ax, s.a, s.b, axial_min, axial_max, 0.0, band)});
    w.zones.push_back({ZoneKind::Traversable,
                       wall_rectangle(s.n, ax, s.a, s.b, axial_min, axial_max, band, span - band)});
    w.zones.push_back({ZoneKind::Forbidden,
                       wall_rectangle(s.n, ax, s.a, s.b, axial_min, axial_max, span - band, span)});
  }
}

void rebuild_wall_geometry(TunnelMap& map, double band) {
  TemplateFrame tf;
  tf.ok = true;
  tf.axis = map.axis_dir;
  tf.up = map.up;
  tf.right = map.axis_dir.cross(map.up);  // axis = up x right
  const double axial_min = tf.axis.dot(map.axis_point);
  const double axial_max = axial_min + (map.extent_max_m - map.extent_min_m);
  const WallOffsets off{map.walls[0].offset_m, map.walls[1].offset_m, map.walls[2].offset_m,
                        map.walls[3].offset_m};
  build_wall_geometry(tf, off, axial_min, axial_max, band, map);
  for (Wall& w : map.walls)
    if (!w.found) w.zones.clear();
}

}  // namespace tunnelmap
