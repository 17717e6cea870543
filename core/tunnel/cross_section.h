#pragma once
// A cross-section of one frame at a station along the tunnel: the points within a slab across
// the axis, in the section's own 2D frame, with the fitted rectangle and, when the design is
// known, the design rectangle. What an engineer compares by eye: does the rectangle follow the
// points, and how far is it from the design.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"
#include "core/tunnel/tunnel_options.h"

namespace tunnelmap {

// Rectangle in section coordinates: `across` to the right looking along the axis, `up` towards
// the roof, metres from the axis at the station.
struct SectionRect {
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  double width() const { return right - left; }
  double height() const { return top - bottom; }
};

struct SectionPoint {
  Eigen::Vector2d at;                        // (across, up)
  WallClass cls = WallClass::Unassigned;     // of the plane the pixel belongs to, if any
  int plane = 0;                             // that plane's label (0: none)
};

struct CrossSection {
  double station_m = 0.0;         // distance ahead of the camera along the axis
  double half_thickness_m = 0.0;  // points within station +- this
  std::vector<SectionPoint> points;
  std::optional<SectionRect> fitted;  // from the walls' planes; a missing wall from the known size
  std::string no_fit_reason;          // why there is no fitted rectangle (empty when there is)
  std::optional<SectionRect> design;  // the design size, centred on the fitted rectangle
  // Where the fitted rectangle's width and height come from (the map's sources): a dimension
  // filled from the design equals it by construction and is no deviation from it.
  DimensionSource width_source = DimensionSource::Unseen, height_source = DimensionSource::Unseen;
  // The cut's own size, from the slab's wall points: per wall, its planes in the slab (each at
  // the median of its points there) clustered into zones, and the outermost zone with a wall's
  // support: the wall's outer surface as the frame's walls and the map measure it, not a middle
  // plate a plate's thickness inside its edge bands; empty where a wall has too few points. The fitted rectangle describes
  // the frame's walls as a whole, which may lie across a change of section.
  std::optional<double> cut_width_m, cut_height_m;
};

// Stations seen by a map: the visible axial extent as distances ahead of the camera.
struct StationRange {
  double from_m = 0.0, to_m = 0.0;
};
StationRange visible_stations(const TunnelMap& map);

// `map` in the camera frame of `cloud` (the per-frame result); `planes` may be empty (points are
// then Unassigned). No fitted rectangle when the map is not detected. At most `max_points`
// points are kept (evenly thinned) so a drawing stays fast. `zone_gap_m`: a wall's planes in the
// slab closer than this are one zone (`tunnel.zone_cluster_mm`, as the frame's walls take it).
CrossSection cross_section(const OrganizedCloud& cloud, const PlaneSegments& planes, const TunnelMap& map,
                           double station_m, double half_thickness_m,
                           std::optional<double> design_width_m = std::nullopt,
                           std::optional<double> design_height_m = std::nullopt,
                           std::size_t max_points = 20000,
                           double zone_gap_m = mm_to_m(tunnel_keys::zone_cluster_mm.default_value));

}  // namespace tunnelmap
