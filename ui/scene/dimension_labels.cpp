#include "ui/scene/dimension_labels.h"

#include "ui/scene/label_points.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

namespace tunnelmap::scene {

namespace {

// A point on the wall's boundary rectangle, `f` of the way from its near edge (the two corners
// nearest the camera, at the origin) to its far edge, across the middle. Far points project
// near the image centre in the along view, where a label is not cut off at the image edge.
Eigen::Vector3d along_wall(const Wall& w, double f) {
  std::array<Eigen::Vector3d, 4> c = w.boundary;
  std::sort(c.begin(), c.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.norm() < b.norm(); });
  const Eigen::Vector3d near = 0.5 * (c[0] + c[1]), far = 0.5 * (c[2] + c[3]);
  return near + f * (far - near);
}

std::string text(const char* name, double metres, DimensionSource source) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s %.3f m", name, metres);
  std::string s = buf;
  if (source == DimensionSource::Context || source == DimensionSource::Design)
    s += std::string(" (") + dimension_source_name(source) + ")";
  return s;
}

bool usable(const Wall& w) {
  if (!w.found) return false;
  for (const auto& p : w.boundary)
    if (!p.allFinite()) return false;
  return true;
}

}  // namespace

vtkSmartPointer<vtkPolyData> make_dimension_labels(const TunnelMap& map, ViewPreset view) {
  LabelPoints labels;
  if (!map.detected) return labels.polydata();
  auto add = [&](const Eigen::Vector3d& p, const std::string& s) { labels.add(p, s); };
  const Wall& floor = usable(map.wall(WallClass::Bottom)) ? map.wall(WallClass::Bottom) : map.wall(WallClass::Top);
  if (map.has_width() && usable(floor) && view != ViewPreset::Side) {
    // Left of the floor's middle: the text runs to the right, away from the legend's corner.
    Eigen::Vector3d to_left = Eigen::Vector3d::Zero();
    if (map.wall(WallClass::Left).found) to_left = -map.wall(WallClass::Left).normal;
    else if (map.wall(WallClass::Right).found) to_left = map.wall(WallClass::Right).normal;
    add(along_wall(floor, 0.5) + 0.3 * map.width_m * to_left, text("width", map.width_m, map.width_source));
  }
  const Wall& side = usable(map.wall(WallClass::Left)) ? map.wall(WallClass::Left) : map.wall(WallClass::Right);
  if (map.has_height() && usable(side) && view != ViewPreset::Top)
    add(along_wall(side, 0.5), text("height", map.height_m, map.height_source));
  return labels.polydata();
}

}  // namespace tunnelmap::scene
