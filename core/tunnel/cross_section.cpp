#include "core/tunnel/cross_section.h"

#include "core/tunnel/zone_clustering.h"
#include "core/util/median.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

namespace tunnelmap {

namespace {

// +1 when the tunnel lies ahead along axis_dir, -1 when axis_dir points back at the camera.
double ahead_sign(const TunnelMap& map) {
  const double mid = map.axis_point.dot(map.axis_dir) + 0.5 * (map.extent_min_m + map.extent_max_m);
  return mid >= 0 ? 1.0 : -1.0;
}

struct SectionFrame {
  Eigen::Vector3d centre, axis, right, up;
};

SectionFrame frame_at(const TunnelMap& map, double station_m) {
  SectionFrame f;
  f.axis = map.axis_dir.normalized() * ahead_sign(map);
  f.up = (map.up - map.up.dot(f.axis) * f.axis).normalized();
  f.right = f.axis.cross(f.up);  // looking along the axis with the roof up
  // The axis point at the station: its distance ahead of the camera is station_m.
  f.centre = map.axis_point + f.axis * (station_m - map.axis_point.dot(f.axis));
  return f;
}

// Where the wall's plane crosses the section's `dir` line through the centre (section coords).
std::optional<double> wall_position(const Wall& w, const SectionFrame& f, const Eigen::Vector3d& dir) {
  if (!w.found || !w.normal.allFinite()) return std::nullopt;
  const double along = w.normal.dot(dir);
  if (std::abs(along) < 0.3) return std::nullopt;  // a wall nearly parallel to that line
  return -(w.normal.dot(f.centre) + w.offset_m) / along;
}

std::optional<SectionRect> fitted_rect(const TunnelMap& map, const SectionFrame& f) {
  if (!map.detected) return std::nullopt;
  auto l = wall_position(map.wall(WallClass::Left), f, f.right);
  auto r = wall_position(map.wall(WallClass::Right), f, f.right);
  auto b = wall_position(map.wall(WallClass::Bottom), f, f.up);
  auto t = wall_position(map.wall(WallClass::Top), f, f.up);
  // A wall out of view: placed from the other one and the size the map knows.
  if (!l && r && map.has_width()) l = *r - map.width_m;
  if (!r && l && map.has_width()) r = *l + map.width_m;
  if (!b && t && map.has_height()) b = *t - map.height_m;
  if (!t && b && map.has_height()) t = *b + map.height_m;
  if (!l || !r || !b || !t) return std::nullopt;
  SectionRect rect{std::min(*l, *r), std::max(*l, *r), std::min(*b, *t), std::max(*b, *t)};
  return rect;
}

// Why one pair of opposite walls gives no edges to the rectangle (empty when it does, as far as
// seen and sized go): both are needed, or one and the size the map knows.
std::string pair_reason(const TunnelMap& map, WallClass a, WallClass b, bool size_known, const char* names[2],
                        const char* size) {
  const bool seen_a = map.wall(a).found, seen_b = map.wall(b).found;
  if (seen_a && seen_b) return "";
  if (!seen_a && !seen_b) return std::string("neither ") + names[0] + " nor " + names[1] + " seen";
  if (size_known) return "";
  // Named by the wall missing: "only the floor seen" read as if the side walls were not seen either.
  return std::string("the ") + (seen_a ? names[1] : names[0]) + " not seen and the " + size + " unknown";
}

// Why a frame has no rectangle to draw: no tunnel, a pair of walls neither seen nor sized, or a
// wall too near the cut's direction to cross it.
std::string no_fit_reason(const TunnelMap& map) {
  if (!map.detected) return "tunnel not detected";
  const char* sides[2] = {"left wall", "right wall"};
  const char* ends[2] = {"floor", "roof"};
  const std::string width = pair_reason(map, WallClass::Left, WallClass::Right, map.has_width(), sides, "width");
  if (!width.empty()) return width;
  const std::string height = pair_reason(map, WallClass::Bottom, WallClass::Top, map.has_height(), ends, "height");
  if (!height.empty()) return height;
  return "a wall lies nearly along the cut";
}

}  // namespace

StationRange visible_stations(const TunnelMap& map) {
  const double s = ahead_sign(map), base = map.axis_point.dot(map.axis_dir);
  const double a = s * (base + map.extent_min_m), b = s * (base + map.extent_max_m);
  return {std::max(0.0, std::min(a, b)), std::max(0.0, std::max(a, b))};
}

namespace {

constexpr std::size_t kMinCutWallPoints = 20;  // fewer: a few stray pixels, not a wall

// `across` (side walls) or `up` (roof, floor) of the wall's outer surface in the slab: its
// planes there, each at the median of its points, clustered into zones as the frame's walls
// are (core/tunnel/zone_clustering.h), and the outermost zone with the support of a wall. A
// wall's middle plate lies a plate's thickness inside its edge bands, and far edge bands break
// into planes of a dozen points each: the median of all its points fell on the middle plate,
// 15 mm short of the width the frame and the map give on a girder with 7.5 mm plates.
std::optional<double> wall_position(const std::vector<SectionPoint>& points, WallClass wall, double zone_gap_m) {
  const bool side = wall == WallClass::Left || wall == WallClass::Right;
  const double outward = wall == WallClass::Left || wall == WallClass::Bottom ? -1.0 : 1.0;
  std::map<int, std::vector<double>> by_plane;
  for (const SectionPoint& p : points)
    if (p.cls == wall) by_plane[p.plane].push_back(outward * (side ? p.at.x() : p.at.y()));
  std::vector<ZonePosition> planes;
  for (auto& [plane, at] : by_plane) {
    const int n = static_cast<int>(at.size());
    planes.push_back({median_of_measured(std::move(at)), n});
  }
  const int support = static_cast<int>(kMinCutWallPoints);
  const std::vector<ZoneCluster> zones = cluster_zone_positions(planes, zone_gap_m, support);
  const int outer = outermost_supported_cluster(zones, support);
  if (outer < 0) return std::nullopt;
  return outward * zones[static_cast<std::size_t>(outer)].offset_m;
}

void measure_cut(CrossSection& s, double zone_gap_m) {
  const auto at = [&](WallClass wall) { return wall_position(s.points, wall, zone_gap_m); };
  const auto left = at(WallClass::Left), right = at(WallClass::Right);
  const auto bottom = at(WallClass::Bottom), top = at(WallClass::Top);
  if (left && right) s.cut_width_m = *right - *left;
  if (bottom && top) s.cut_height_m = *top - *bottom;
}

}  // namespace

CrossSection cross_section(const OrganizedCloud& cloud, const PlaneSegments& planes, const TunnelMap& map,
                           double station_m, double half_thickness_m, std::optional<double> design_width_m,
                           std::optional<double> design_height_m, std::size_t max_points, double zone_gap_m) {
  CrossSection out;
  out.station_m = station_m;
  out.half_thickness_m = half_thickness_m;
  const SectionFrame f = frame_at(map, station_m);
  const bool labelled = planes.labels.size() == cloud.points.size();
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (!OrganizedCloud::valid(p)) continue;
    const Eigen::Vector3d d = p.cast<double>() - f.centre;
    if (std::abs(d.dot(f.axis)) > half_thickness_m) continue;
    SectionPoint sp;
    sp.at = {d.dot(f.right), d.dot(f.up)};
    if (labelled) {
      const int id = planes.labels[i];
      if (id > 0 && static_cast<std::size_t>(id) <= map.plane_classes.size()) {
        sp.cls = map.plane_classes[static_cast<std::size_t>(id - 1)];
        sp.plane = id;
      }
    }
    out.points.push_back(sp);
  }
  measure_cut(out, zone_gap_m);  // on every point of the slab: a thinned plane may fall below a wall's support
  if (max_points > 0 && out.points.size() > max_points) {
    const double step = static_cast<double>(out.points.size()) / static_cast<double>(max_points);
    std::vector<SectionPoint> kept;
    kept.reserve(max_points);
    for (std::size_t k = 0; k < max_points; ++k) kept.push_back(out.points[static_cast<std::size_t>(k * step)]);
    out.points.swap(kept);
  }
  out.fitted = fitted_rect(map, f);
  if (!out.fitted) out.no_fit_reason = no_fit_reason(map);
  if (out.fitted) {
    out.width_source = map.width_source;
    out.height_source = map.height_source;
  }
  if (out.fitted && design_width_m && design_height_m && *design_width_m > 0 && *design_height_m > 0) {
    const double cx = 0.5 * (out.fitted->left + out.fitted->right);
    const double cy = 0.5 * (out.fitted->bottom + out.fitted->top);
    out.design = SectionRect{cx - 0.5 * *design_width_m, cx + 0.5 * *design_width_m, cy - 0.5 * *design_height_m,
                             cy + 0.5 * *design_height_m};
  }
  return out;
}

}  // namespace tunnelmap
