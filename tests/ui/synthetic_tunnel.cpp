#include "tests/ui/synthetic_tunnel.h"

#include <cmath>
#include <limits>

namespace tunnelmap::test {

namespace {
// Wall classes in camera frame (x right, y down, z forward); normals point into the tunnel.
struct WallDef {
  WallClass cls;
  Eigen::Vector3d normal;
  double offset;  // normal.dot(x) + offset = 0
};
}  // namespace

scene::ProcessedFrame make_synthetic_tunnel(double w, double h, double length) {
  scene::ProcessedFrame out;
  DepthFrame& f = out.frame;
  f.width = 640;
  f.height = 480;
  f.intrinsics = Intrinsics::primesense_vga();
  f.depth_units_per_m = 1000.0;
  f.depth.assign(static_cast<std::size_t>(f.width) * f.height, 0.0f);
  f.source = "synthetic";
  const WallDef walls[4] = {{WallClass::Left, {1, 0, 0}, w / 2},
                            {WallClass::Right, {-1, 0, 0}, w / 2},
                            {WallClass::Top, {0, 1, 0}, h / 2},
                            {WallClass::Bottom, {0, -1, 0}, h / 2}};
  OrganizedCloud& cloud = out.result.cloud;
  cloud.width = f.width;
  cloud.height = f.height;
  cloud.intrinsics = f.intrinsics;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud.points.assign(f.depth.size(), Eigen::Vector3f(nan, nan, nan));
  cloud.normals = cloud.points;
  PlaneSegments& planes = out.result.planes;
  planes.width = f.width;
  planes.height = f.height;
  planes.labels.assign(f.depth.size(), 0);
  for (int k = 0; k < 4; ++k) {
    PlaneSegment p;
    p.id = k + 1;
    p.normal = walls[k].normal;
    p.mean_normal = walls[k].normal;
    p.offset_m = walls[k].offset;
    planes.planes.push_back(p);
  }
  // Ray-cast each pixel against the four walls; the nearest hit within the length wins.
  for (int v = 0; v < f.height; ++v)
    for (int u = 0; u < f.width; ++u) {
      const Eigen::Vector3d ray = f.intrinsics.ray(u, v);
      double best = std::numeric_limits<double>::infinity();
      int best_k = -1;
      for (int k = 0; k < 4; ++k) {
        const double denom = walls[k].normal.dot(ray);
        if (denom >= 0) continue;  // facing away
        const double t = -walls[k].offset / denom;  // z of the hit (ray has z = 1)
        if (t > 0 && t < best) {
          best = t;
          best_k = k;
        }
      }
      if (best_k < 0 || best > length) continue;
      const std::size_t i = static_cast<std::size_t>(v) * f.width + u;
      f.depth[i] = static_cast<float>(best * 1000.0);
      cloud.points[i] = (ray * best).cast<float>();
      cloud.normals[i] = walls[best_k].normal.cast<float>();
      planes.labels[i] = best_k + 1;
      planes.planes[best_k].points++;
    }
  // The map: every wall found, boundary over z in [0.5, length], a traversable middle strip and
  // two forbidden edge bands per wall.
  TunnelMap& map = out.result.map;
  map.detected = true;
  map.status = TunnelStatus::Ok;
  map.width_m = w;
  map.height_m = h;
  map.axis_point = Eigen::Vector3d::Zero();
  map.axis_dir = Eigen::Vector3d::UnitZ();
  map.up = -Eigen::Vector3d::UnitY();
  map.extent_min_m = 0.5;
  map.extent_max_m = length;
  const double z0 = 0.5, z1 = length, band = 0.15;
  for (int k = 0; k < 4; ++k) {
    Wall& wall = map.wall(walls[k].cls);
    wall.cls = walls[k].cls;
    wall.found = true;
    wall.normal = walls[k].normal;
    wall.offset_m = walls[k].offset;
    // In-wall "across" direction and the half size across the wall.
    const bool side_wall = k < 2;
    const Eigen::Vector3d across = side_wall ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    const double half = side_wall ? h / 2 : w / 2;
    const Eigen::Vector3d base = -walls[k].normal * walls[k].offset;  // closest wall point to axis
    auto at = [&](double a, double z) { return Eigen::Vector3d(base + across * a + Eigen::Vector3d::UnitZ() * z); };
    wall.boundary = {at(-half, z0), at(half, z0), at(half, z1), at(-half, z1)};
    ZoneRect lo{ZoneKind::Forbidden, {at(-half, z0), at(-half + band, z0), at(-half + band, z1), at(-half, z1)}};
    ZoneRect mid{ZoneKind::Traversable, {at(-half + band, z0), at(half - band, z0), at(half - band, z1), at(-half + band, z1)}};
    ZoneRect hi{ZoneKind::Forbidden, {at(half - band, z0), at(half, z0), at(half, z1), at(half - band, z1)}};
    wall.zones = {lo, mid, hi};
    map.plane_classes.push_back(walls[k].cls);
    map.plane_outlier.push_back(false);
  }
  return out;
}

}  // namespace tunnelmap::test
