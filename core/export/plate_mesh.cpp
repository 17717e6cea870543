#include "core/export/plate_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap {

namespace {

// The cross-section at a plate: the compartment the robot leaves there, else the one it enters.
bool plate_size(const GirderStructure& girder, double station, double& width, double& height) {
  constexpr double kAt = 0.05;
  for (int pass = 0; pass < 2; ++pass)
    for (const Compartment& c : girder.compartments) {
      const double end = pass == 0 ? c.to_m : c.from_m;
      if (std::abs(end - station) > kAt || !std::isfinite(c.width_m) || !std::isfinite(c.height_m)) continue;
      width = c.width_m;
      height = c.height_m;
      return true;
    }
  return false;
}

// Signed distance from a rounded rectangle of half sizes (a, b) and corner radius r.
double rounded_rectangle_distance(const Eigen::Vector2d& p, double a, double b, double r) {
  r = std::min({r, a, b});
  const Eigen::Vector2d q(std::abs(p.x()) - (a - r), std::abs(p.y()) - (b - r));
  return q.cwiseMax(0.0).norm() + std::min(std::max(q.x(), q.y()), 0.0) - r;
}

// How far from its centre the opening's outline lies in direction `u`.
double opening_radius(const PlateOpening& o, const Eigen::Vector2d& u) {
  const double a = 0.5 * o.width_m, b = 0.5 * o.height_m;
  if (o.shape != "rounded_rectangle") return 1.0 / std::hypot(u.x() / a, u.y() / b);
  double lo = 0.0, hi = std::hypot(a, b);
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rounded_rectangle_distance(mid * u, a, b, o.corner_radius_m) < 0 ? lo : hi) = mid;
  }
  return lo;
}

// Where a ray from `c` in direction `u` leaves the rectangle [-w/2, w/2] x [-h/2, h/2].
double exit_distance(const Eigen::Vector2d& c, const Eigen::Vector2d& u, double w, double h) {
  double t = std::numeric_limits<double>::infinity();
  const double half[2] = {0.5 * w, 0.5 * h};
  for (int k = 0; k < 2; ++k)
    if (std::abs(u[k]) > 1e-12) t = std::min(t, ((u[k] > 0 ? half[k] : -half[k]) - c[k]) / u[k]);
  return std::max(0.0, t);
}

}  // namespace

std::vector<PlateOutline> plate_outlines(const StationMap& map) {
  std::vector<PlateOutline> out;
  for (const Diaphragm& d : map.girder.diaphragms) {
    PlateOutline p;
    if (!plate_size(map.girder, d.station_m, p.width_m, p.height_m)) continue;
    const CentrelineFrame f = map.frame_at(d.station_m);  // the girder's directions at the plate
    const Eigen::Vector3d along = d.normal.dot(f.axis) < 0 ? -d.normal : d.normal;
    p.centre = d.point;
    p.up = (f.up - along * along.dot(f.up)).normalized();
    p.left = p.up.cross(along);
    if (d.manhole) {
      const Manhole& m = *d.manhole;
      PlateOpening o;
      o.lateral_m = p.left.dot(m.center - d.point);
      o.vertical_m = p.up.dot(m.center - d.point);
      o.width_m = m.width_m;
      o.height_m = m.height_m;
      o.shape = m.shape;
      o.corner_radius_m = m.corner_radius_m;
      // An opening whose centre lies outside the cross-section contradicts it: no plate drawn.
      if (std::abs(o.lateral_m) >= 0.5 * p.width_m || std::abs(o.vertical_m) >= 0.5 * p.height_m) continue;
      p.opening = o;
    }
    out.push_back(p);
  }
  return out;
}

PlateMesh triangulate_plate(const PlateOutline& plate, int samples) {
  PlateMesh mesh;
  auto world = [&](const Eigen::Vector2d& q) { return plate.centre + plate.left * q.x() + plate.up * q.y(); };
  const double w = plate.width_m, h = plate.height_m;
  if (!plate.opening) {
    for (const Eigen::Vector2d& q : {Eigen::Vector2d(-w / 2, -h / 2), Eigen::Vector2d(w / 2, -h / 2),
                                     Eigen::Vector2d(w / 2, h / 2), Eigen::Vector2d(-w / 2, h / 2)})
      mesh.vertices.push_back(world(q));
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
  }
  const PlateOpening& o = *plate.opening;
  const Eigen::Vector2d c(o.lateral_m, o.vertical_m);
  std::vector<double> angles;
  for (int k = 0; k < samples; ++k) angles.push_back(2.0 * M_PI * k / samples);
  for (const Eigen::Vector2d& corner : {Eigen::Vector2d(-w / 2, -h / 2), Eigen::Vector2d(w / 2, -h / 2),
                                       Eigen::Vector2d(w / 2, h / 2), Eigen::Vector2d(-w / 2, h / 2)}) {
    const double a = std::atan2(corner.y() - c.y(), corner.x() - c.x());
    angles.push_back(a < 0 ? a + 2.0 * M_PI : a);
  }
  std::sort(angles.begin(), angles.end());
  for (double a : angles) {
    const Eigen::Vector2d u(std::cos(a), std::sin(a));
    const double outer = exit_distance(c, u, w, h);
    const double inner = std::min(opening_radius(o, u), outer);
    mesh.vertices.push_back(world(c + inner * u));
    mesh.vertices.push_back(world(c + outer * u));
  }
  const int n = static_cast<int>(angles.size());
  for (int k = 0; k < n; ++k) {
    const int i0 = 2 * k, o0 = 2 * k + 1, i1 = 2 * ((k + 1) % n), o1 = 2 * ((k + 1) % n) + 1;
    mesh.triangles.push_back({i0, o0, o1});
    mesh.triangles.push_back({i0, o1, i1});
  }
  return mesh;
}

}  // namespace tunnelmap
