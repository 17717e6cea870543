#include "core/mapping/station_map_builder.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <unordered_map>

#include "core/mapping/end_wall_trim.h"
#include "core/mapping/frame_walls.h"
#include "core/mapping/section_evidence.h"
#include "core/mapping/slam_patches.h"
#include "core/mapping/station_sections.h"
#include "core/tunnel/tunnel_detector.h"
#include "core/tunnel/wall_geometry.h"
#include "core/tunnel/zone_clustering.h"
#include "core/util/median.h"

namespace tunnelmap {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

// station_map_options: core/mapping/map_options.cpp, beside the map.* declarations.

StationMapBuilder::StationMapBuilder(StationMapOptions options, TunnelOptions tunnel)
    : options_(std::move(options)), tunnel_(tunnel) {}

void StationMapBuilder::follow(Centreline line) {
  line_ = std::move(line);
  have_line_ = true;
}

bool StationMapBuilder::ensure_frame(const TunnelMap& map, const Eigen::Isometry3d& T) {
  if (!have_origin_) {
    // Station 0: the first frame's camera centre, positive in its viewing direction.
    origin_ = T.translation();
    first_view_ = T.linear().col(2);
    have_origin_ = true;
  }
  if (have_frame_) return true;
  if (!map.detected) return false;
  // The axis and up of the first detected frame, in the world frame; both are unit and
  // perpendicular (the template fit makes them so).
  axis_ = (T.linear() * map.axis_dir).normalized();
  if (axis_.dot(first_view_) < 0) axis_ = -axis_;
  up_ = T.linear() * map.up;
  up_ = (up_ - axis_ * axis_.dot(up_)).normalized();
  // Without a fitted centre line, stations run along this frame's axis.
  if (!have_line_) line_ = Centreline::straight(origin_, axis_, up_);
  have_frame_ = true;
  return true;
}

void StationMapBuilder::frame_pieces(const TunnelMap& m, const FrameWalls& walls,
                                     const Eigen::Isometry3d& T, int frame, Pieces& out) const {
  out.clear();
  if (walls.samples.empty()) return;
  Eigen::Vector3d own[4];
  for (int k = 0; k < 4; ++k)
    own[k] = (-(T.linear() * m.walls[k].normal)).normalized();  // inward -> outward
  const double inv_step = 1.0 / options_.station_step_m;
  const int camera_node = line_.locate(T.translation()).node;
  // (station, plane) -> sums; a plane has one wall.
  struct Sum {
    double position = 0, own_position = 0, range = 0;
    int points = 0;
    int wall = 0;
  };
  std::unordered_map<long long, Sum> sums;
  for (const WallSample& ws : walls.samples) {
    // A plane the frame saw deeper inside its own wall than any zone lies is not taken for the
    // wall: seen through a manhole from 3-4 m, the edges of the opening look like a stretch of
    // wall just past the plate, 0.1-0.7 m inside, where nothing else measures the wall. A
    // narrower section the frame did not split off is lost with it; nearer frames measure it.
    if (ws.wall >= 4 || ws.inside) continue;
    const Eigen::Vector3d p = T * ws.point.cast<double>();
    // The wall's position outward from the line, in the line's own frame at the point's station.
    const LinePosition at = line_.locate(p, camera_node);
    const double outward[4] = {at.lateral_m, -at.lateral_m, at.vertical_m, -at.vertical_m};
    const int station = static_cast<int>(std::floor(at.station_m * inv_step));
    // Multiplied, not shifted: a station behind the first camera (a look back) is negative.
    Sum& s = sums[static_cast<long long>(station) * (1LL << 20) ^ ws.plane];
    s.position += outward[ws.wall] * ws.points;
    s.own_position += own[ws.wall].dot(p - origin_) * ws.points;
    s.range += static_cast<double>(ws.point.z()) * ws.points;
    s.points += ws.points;
    s.wall = ws.wall;
  }
  for (const auto& [key, s] : sums) {
    const int station = static_cast<int>(key >> 20);
    out[station].push_back(
        {station, s.wall, frame, s.points, s.position / s.points, s.own_position / s.points, s.range / s.points});
  }
}

std::vector<StationMapBuilder::WallProfile> StationMapBuilder::profile(const Pieces& pieces, int k0, int k1,
                                                                       bool own, const double* known_step,
                                                                       double* seen_step) const {
  std::vector<WallProfile> out(static_cast<std::size_t>(std::max(0, k1 - k0 + 1)));
  for (WallProfile& w : out) {
    std::fill(std::begin(w.wall_m), std::end(w.wall_m), kNaN);
    w.frames = 0;
  }
  if (out.empty()) return out;
  // Per station and wall: zone clusters of the pieces, outermost supported one; a wall whose
  // only supported cluster is its middle plate gets the edge step seen elsewhere (the symmetric
  // zone prior of single frames, applied along the tunnel).
  std::vector<std::vector<double>> steps(4);
  std::vector<std::array<std::vector<ZoneCluster>, 4>> clusters(out.size());
  std::vector<ZonePosition> positions;
  std::vector<int> frames;
  for (auto it = pieces.lower_bound(k0); it != pieces.end() && it->first <= k1; ++it) {
    const int k = it->first;
    const std::vector<Piece>& here = it->second;
    WallProfile& wp = out[static_cast<std::size_t>(k - k0)];
    frames.clear();
    for (const Piece& p : here) frames.push_back(p.frame);
    std::sort(frames.begin(), frames.end());
    wp.frames = static_cast<int>(std::unique(frames.begin(), frames.end()) - frames.begin());
    for (int c = 0; c < 4; ++c) {
      // Near views alone where they have the support: far planes (3-5 m) are noisier and may
      // span a plate step (an edge band and its middle plate in one plane), whose positions lie
      // between the two zones and would chain them into one cluster.
      int near_points = 0;
      for (const Piece& p : here)
        if (p.wall == c && p.range_m <= options_.near_range_m) near_points += p.points;
      const double max_range = near_points >= options_.min_support_points
                                   ? options_.near_range_m
                                   : std::numeric_limits<double>::infinity();
      positions.clear();
      for (const Piece& p : here)
        if (p.wall == c && p.range_m <= max_range)
          positions.push_back({own ? p.own_position_m : p.position_m, p.points});
      if (positions.empty()) continue;
      auto& cl = clusters[static_cast<std::size_t>(k - k0)][c];
      cluster_zone_positions(positions, options_.zone_gap_m, options_.min_support_points, cl);
      const int best = outermost_supported_cluster(cl, options_.min_support_points);
      if (best < 0) continue;
      wp.wall_m[c] = cl[best].offset_m;
      const double step =
          observed_edge_step(cl, options_.min_support_points, options_.max_symmetric_step_m);
      if (step > 0) steps[c].push_back(step);
    }
  }
  double step[4];
  for (int c = 0; c < 4; ++c) step[c] = median_of_measured(steps[c]);
  if (seen_step) std::copy(step, step + 4, seen_step);
  if (options_.max_symmetric_step_m <= 0) return out;
  if (known_step)
    for (int c = 0; c < 4; ++c)
      if (std::isnan(step[c])) step[c] = known_step[c];
  const int opposite[4] = {1, 0, 3, 2};
  for (std::size_t k = 0; k < out.size(); ++k)
    for (int c = 0; c < 4; ++c) {
      if (std::isnan(out[k].wall_m[c])) continue;
      if (!single_supported_zone(clusters[k][c], options_.min_support_points)) continue;
      const double s = !std::isnan(step[c]) ? step[c] : step[opposite[c]];
      if (std::isnan(s)) continue;
      // Edge band or middle plate? The neighbours that saw both tell; alone, the larger
      // middle plate is the one seen (as in single frames).
      double nearest = kNaN;
      for (int d = 1; d <= 5 && std::isnan(nearest); ++d)
        for (const int kk : {static_cast<int>(k) - d, static_cast<int>(k) + d}) {
          if (kk < 0 || kk >= static_cast<int>(out.size())) continue;
          if (observed_edge_step(clusters[kk][c], options_.min_support_points,
                                 options_.max_symmetric_step_m) > 0)
            nearest = clusters[kk][c][outermost_supported_cluster(clusters[kk][c],
                                                                  options_.min_support_points)]
                          .offset_m;
        }
      if (!std::isnan(nearest) && std::abs(out[k].wall_m[c] - nearest) < 0.5 * s) continue;
      out[k].wall_m[c] += s;
    }
  return out;
}

std::vector<StationMapBuilder::WallProfile> StationMapBuilder::own_profile(const Pieces& own,
                                                                           double* seen_step) const {
  return profile(own, own.begin()->first, own.rbegin()->first, true, known_edge_step_, seen_step);
}

void StationMapBuilder::own_parts(TunnelMap& m, const Pieces& own, int camera_station) const {
  const int f0 = own.begin()->first;
  const std::vector<WallProfile> mine = own_profile(own);
  std::vector<double> w(mine.size()), h(mine.size());
  for (std::size_t k = 0; k < mine.size(); ++k) {
    w[k] = mine[k].wall_m[0] + mine[k].wall_m[1];
    h[k] = mine[k].wall_m[2] + mine[k].wall_m[3];
  }
  const SectionSplit split = split_sections(w, h, options_.section_change_mm / 1000.0,
                                            options_.min_section_stations);
  const double step = options_.station_step_m;
  m.parts.clear();
  for (const SectionRun& run : split.sections)
    m.parts.push_back({(f0 + run.first) * step, (f0 + run.last + 1) * step, run.width_m, run.height_m});
  // Nearest the camera first: the frame's values are those of the nearest part that has them.
  const double cam = (camera_station + 0.5) * step;
  std::vector<const TunnelPart*> order;
  for (const TunnelPart& p : m.parts) order.push_back(&p);
  std::stable_sort(order.begin(), order.end(), [&](const TunnelPart* a, const TunnelPart* b) {
    const auto gap = [&](const TunnelPart* p) { return std::max({0.0, p->from_m - cam, cam - p->to_m}); };
    return gap(a) < gap(b);
  });
  bool changed = false;
  for (int a : {0, 2}) {
    if ((a == 0 ? m.width_source : m.height_source) != DimensionSource::Measured) continue;
    for (const TunnelPart* p : order) {
      const double v = a == 0 ? p->width_m : p->height_m;
      if (std::isnan(v)) continue;
      double& value = a == 0 ? m.width_m : m.height_m;
      // Both walls move by half the change, so the drawn map keeps its centre line.
      const double d = 0.5 * (v - value);
      m.walls[a].offset_m += d;
      m.walls[a + 1].offset_m += d;
      value = v;
      changed = true;
      break;
    }
  }
  if (changed) {
    rebuild_wall_geometry(m, tunnel_.forbidden_band_m);
    if (m.status == TunnelStatus::Ok) describe_tunnel_map(m);
  }
}

void StationMapBuilder::apply_context(TunnelMap& m, const Pieces& own,
                                      const Eigen::Isometry3d& T) const {
  const int camera_station =
      static_cast<int>(std::floor(line_.locate(T.translation()).station_m / options_.station_step_m));
  if (!own.empty()) own_parts(m, own, camera_station);
  if (pieces_.empty()) return;
  // The map around the stations this frame sees (a window keeps the cost per frame flat as the
  // map grows); the whole map only when the window holds no value to infer from.
  const int margin = 5;
  int k0 = own.empty() ? camera_station : own.begin()->first - margin;
  int k1 = own.empty() ? camera_station + static_cast<int>(std::ceil(3.0 / options_.station_step_m))
                       : own.rbegin()->first + margin;
  std::vector<WallProfile> map = profile(pieces_, k0, k1);
  const auto at = [&](int k) -> const WallProfile* {
    return k < k0 || k > k1 ? nullptr : &map[static_cast<std::size_t>(k - k0)];
  };
  const auto dim = [](const WallProfile& w, int a) { return w.wall_m[a] + w.wall_m[a + 1]; };

  // Compared with the map at the stations it sees: a frame that disagrees, where at least two
  // earlier frames measured, at most of them is an outlier. Stations new to the map are not
  // compared, so a change of section is taken once frames see it.
  if (!own.empty()) {
    const int f0 = own.begin()->first, f1 = own.rbegin()->first;
    const std::vector<WallProfile> mine = own_profile(own);
    int compared = 0, disagree = 0;
    double worst = 0.0;
    int worst_pair = 0;
    for (int k = f0; k <= f1; ++k) {
      // The map's own dimensions there, each from frames that saw both walls of the pair:
      // an error of the earlier frames' poses does not enter.
      const Dims here = station_dims(k);
      const WallProfile* w = at(k);
      const WallProfile& f = mine[static_cast<std::size_t>(k - f0)];
      for (int a : {0, 2}) {
        double d = kNaN;
        if (options_.per_frame_sizes) {
          if ((a == 0 ? here.width_frames : here.height_frames) < 2) continue;
          d = dim(f, a) - (a == 0 ? here.width_m : here.height_m);
        } else {
          if (!w || w->frames < 2) continue;
          d = dim(f, a) - dim(*w, a);
        }
        if (std::isnan(d)) continue;
        ++compared;
        if (std::abs(d) > tunnel_.context_tolerance_m) ++disagree;
        if (std::abs(d) > std::abs(worst)) worst = d, worst_pair = a;
      }
    }
    if (compared >= 3 && 2 * disagree > compared) {
      m.detected = false;
      m.status = TunnelStatus::InconsistentWithContext;
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "%s differs from the map at %d of %d stations it sees (by up to %.0f mm, "
                    "tolerance %.0f mm)",
                    worst_pair == 0 ? "width" : "height", disagree, compared, worst * 1000.0,
                    tunnel_.context_tolerance_m * 1000.0);
      m.reason = buf;
      return;
    }
  }

  // Missing walls from the map in the world frame: the missing wall's position there (at the
  // stations the frame sees, else at the nearest station that has one) with the frame's own
  // position of the wall opposite; when the frame saw neither, the map's dimension.
  int f0 = 0, f1 = 0;
  if (!own.empty()) {
    f0 = own.begin()->first;
    f1 = own.rbegin()->first;
  } else {  // nothing measured: the stations in front of the camera
    f0 = camera_station;
    f1 = camera_station + static_cast<int>(std::ceil(2.0 / options_.station_step_m));
  }
  const std::vector<WallProfile> mine = own.empty() ? std::vector<WallProfile>() : profile(own, f0, f1);
  const auto own_position = [&](int c) {
    std::vector<double> v;
    for (const WallProfile& w : mine)
      if (!std::isnan(w.wall_m[c])) v.push_back(w.wall_m[c]);
    return median_of_measured(v);
  };
  // Median of `value(k)` over the frame's stations, else over the nearest stations with one.
  const auto from_map = [&](const auto& value, bool expand) {
    std::vector<double> values;
    for (int k = f0; k <= f1; ++k)
      if (const WallProfile* w = at(k); w && !std::isnan(value(*w))) values.push_back(value(*w));
    if (!expand) return median_of_measured(values);
    if (values.empty() && (k0 > pieces_.begin()->first || k1 < pieces_.rbegin()->first)) {
      k0 = pieces_.begin()->first;
      k1 = pieces_.rbegin()->first;
      map = profile(pieces_, k0, k1);
    }
    for (int d = 1; values.empty() && d <= k1 - k0 + (f1 - f0); ++d)
      for (const int k : {f0 - d, f1 + d})
        if (const WallProfile* w = at(k); w && !std::isnan(value(*w))) values.push_back(value(*w));
    return median_of_measured(values);
  };
  bool changed = false;
  for (int a : {0, 2}) {
    DimensionSource& source = a == 0 ? m.width_source : m.height_source;
    double& dim_value = a == 0 ? m.width_m : m.height_m;
    if (source == DimensionSource::Measured) continue;
    int seen = -1;
    for (int c : {a, a + 1})
      if (m.walls[c].source == DimensionSource::Measured) seen = c;
    // The map's dimension where the frame looks is the best evidence (no pose error enters);
    // else the missing wall's position, which needs only that wall to have been seen there.
    const auto map_dim = [&](const WallProfile& w) { return dim(w, a); };
    double value = from_map(map_dim, false);
    if (std::isnan(value) && seen >= 0) {
      const int missing = seen ^ 1;
      value = own_position(seen) +
              from_map([&](const WallProfile& w) { return w.wall_m[missing]; }, true);
    }
    if (std::isnan(value)) value = from_map(map_dim, true);
    if (std::isnan(value)) continue;
    source = DimensionSource::Context;
    dim_value = value;
    if (seen >= 0) {
      Wall& wm = m.walls[seen ^ 1];
      wm.found = true;
      wm.source = DimensionSource::Context;
      wm.offset_m = value - m.walls[seen].offset_m;
      changed = true;
    }
  }
  if (changed) rebuild_wall_geometry(m, tunnel_.forbidden_band_m);
  describe_tunnel_map(m);
}

void StationMapBuilder::add_frame(int index, TunnelMap& map, const FrameWalls& walls,
                                  const Eigen::Isometry3d& T) {
  const bool placed = ensure_frame(map, T);
  if (placed && !map.detected) {
    // It found no cross-section (a plate fills its view, the walls beside it too short for a
    // zone), yet its pose places the plates it faces as well as any frame's: often the only view
    // of a plate just behind another, through that one's opening.
    add_plate_views(index, walls, T, PlateCheck::AcrossMapAxis);
  } else if (placed) {
    Pieces own;
    frame_pieces(map, walls, T, index, own);
    apply_context(map, own, T);
    if (map.detected) {
      for (auto& [k, v] : own) {
        std::vector<Piece>& dst = pieces_[k];
        dst.insert(dst.end(), v.begin(), v.end());
      }
      add_plate_views(index, walls, T, PlateCheck::AcrossOwnAxis);
      record_frame_dims(index, own);
    }
  }
  scans_.push_back({map, T, index});
  TunnelMap& kept = scans_.back().map;  // per-plane arrays are not needed for the map
  kept.plane_classes.clear();
  kept.plane_outlier.clear();
  kept.plane_candidate_classes.clear();
}

void StationMapBuilder::record_frame_dims(int frame, const Pieces& own) {
  if (own.empty()) return;
  const int f0 = own.begin()->first;
  double seen[4];
  const std::vector<WallProfile> mine = own_profile(own, seen);
  for (int c = 0; c < 4; ++c) {
    std::vector<double>& steps = own_edge_steps_[static_cast<std::size_t>(c)];
    if (std::isnan(seen[c])) continue;
    steps.push_back(seen[c]);
    if (steps.size() > kRecentEdgeSteps) steps.erase(steps.begin());
    known_edge_step_[c] = median_of_measured(steps);
  }
  for (const auto& [k, pieces] : own) {
    const WallProfile& w = mine[static_cast<std::size_t>(k - f0)];
    const double width = w.wall_m[0] + w.wall_m[1], height = w.wall_m[2] + w.wall_m[3];
    if (std::isnan(width) && std::isnan(height)) continue;
    double range = 0;
    int points = 0;
    for (const Piece& p : pieces) range += p.range_m * p.points, points += p.points;
    frame_dims_[k].push_back({frame, width, height, points > 0 ? range / points : kNaN});
  }
}

std::vector<FrameStationSize> StationMapBuilder::frame_views(int first_station) const {
  std::vector<FrameStationSize> views;
  for (const auto& [station, frames] : frame_dims_)
    for (const FrameDims& f : frames) views.push_back({f.frame, station - first_station, f.width_m, f.height_m});
  return views;
}

StationMapBuilder::Dims StationMapBuilder::station_dims(int station) const {
  Dims d{kNaN, kNaN, 0, 0};
  const auto it = frame_dims_.find(station);
  if (it == frame_dims_.end()) return d;
  for (const bool near_only : {true, false}) {
    std::vector<double> w, h;
    for (const FrameDims& f : it->second) {
      if (near_only && !(f.range_m <= options_.near_range_m)) continue;
      if (!std::isnan(f.width_m)) w.push_back(f.width_m);
      if (!std::isnan(f.height_m)) h.push_back(f.height_m);
    }
    if (std::isnan(d.width_m) && !w.empty()) d.width_m = median_of_measured(w), d.width_frames = static_cast<int>(w.size());
    if (std::isnan(d.height_m) && !h.empty()) d.height_m = median_of_measured(h), d.height_frames = static_cast<int>(h.size());
  }
  return d;
}

void StationMapBuilder::set_unchecked_frames(std::vector<int> frames) {
  std::sort(frames.begin(), frames.end());
  unchecked_frames_ = std::move(frames);
}

void StationMapBuilder::add_plate_views(int frame, const FrameWalls& walls, const Eigen::Isometry3d& T,
                                        PlateCheck check) {
  const int camera_node = line_.locate(T.translation()).node;
  const auto map_coordinates = [&](const Eigen::Vector3f& camera_point) {
    const LinePosition at = line_.locate(T * camera_point.cast<double>(), camera_node);
    return Eigen::Vector3d(at.station_m, at.lateral_m, at.vertical_m);
  };
  std::map<int, PlateView> by_plane;
  for (const WallSample& s : walls.samples) {
    if (s.wall != kTransverseSample) continue;
    PlateView& v = by_plane[s.plane];
    v.frame = frame;
    v.checked = !std::binary_search(unchecked_frames_.begin(), unchecked_frames_.end(), frame);
    v.samples.push_back(map_coordinates(s.point));
    v.weights.push_back(s.points);
  }
  for (const RimPoint& r : walls.rims)
    if (const auto it = by_plane.find(r.plane); it != by_plane.end())
      it->second.rim.push_back(map_coordinates(r.point));
  // A view the cloud's range cut places its plate too near; nearer views place it.
  const std::vector<int> cut = plates_cut_by_range(walls, options_.cloud_max_range_m, options_.point_sigma_m);
  for (auto& [plane, v] : by_plane) {
    if (check == PlateCheck::AcrossMapAxis && !view_lies_across_axis(v, kTransverseMaxAngleDeg)) continue;
    const bool too_near = std::binary_search(cut.begin(), cut.end(), plane);
    (too_near ? range_cut_plates_ : plates_).push_back(std::move(v));
  }
}

namespace {

// A world-frame map of one section: its four walls at their positions from the centre line
// (NaN: unknown, drawn at the opposite wall's mirror and not part of the map), swept from `s0`
// to `s1` along the axis.
TunnelMap section_map(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                      const Eigen::Vector3d& up, const double wall_m[4], double s0, double s1,
                      double band) {
  TunnelMap m;
  m.detected = true;
  m.status = TunnelStatus::Ok;
  m.axis_dir = axis;
  m.up = up;
  double pos[4];
  for (int c = 0; c < 4; ++c) {
    const double mirror = wall_m[c ^ 1];
    pos[c] = !std::isnan(wall_m[c]) ? wall_m[c] : !std::isnan(mirror) ? mirror : 0.5;
    m.walls[c].found = !std::isnan(wall_m[c]);
    m.walls[c].source = m.walls[c].found ? DimensionSource::Measured : DimensionSource::Unseen;
    m.walls[c].offset_m = pos[c];
  }
  m.width_m = pos[0] + pos[1];
  m.height_m = pos[2] + pos[3];
  TemplateFrame tf;
  tf.ok = true;
  tf.axis = axis;
  tf.up = up;
  tf.right = axis.cross(up);
  build_wall_geometry(tf, {pos[0], pos[1], pos[2], pos[3]}, s0, s1, band, m);
  for (Wall& w : m.walls)
    if (!w.found) w.zones.clear();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = origin;
  return transform_map(m, T);
}

// The section between stations s0 and s1 drawn along the reference line: one straight box on a
// straight line; on a fitted line, boxes of at most kDrawnPieceM each along the line's frame at
// its middle (a 1 m chord departs from a 150 m radius by under 1 mm).
constexpr double kDrawnPieceM = 1.0;

void add_section_maps(const Centreline& line, const double wall_m[4], double s0, double s1, double band,
                      std::vector<TunnelMap>& out) {
  const int pieces = line.is_straight() ? 1 : std::max(1, static_cast<int>(std::ceil((s1 - s0) / kDrawnPieceM)));
  for (int i = 0; i < pieces; ++i) {
    const double a = s0 + (s1 - s0) * i / pieces, b = s0 + (s1 - s0) * (i + 1) / pieces;
    const CentrelineFrame f = line.frame_at(0.5 * (a + b));
    // The piece's frame, placed so that station s lies at origin + s * axis.
    const Eigen::Vector3d origin = f.point - f.station_m * f.axis;
    out.push_back(section_map(origin, f.axis, f.up, wall_m, a, b, band));
  }
}

// A pose that found no cross-section may still have seen the plates it faced (a diaphragm
// filling its view), which the map took: its rescan is for the section only, and its message
// says which plates it saw.
void note_plates_seen(StationMap& m) {
  for (PoseGroupStatus& p : m.poses) {
    if (!p.rescan) continue;
    std::vector<std::string> seen_plates;
    for (const Diaphragm& d : m.girder.diaphragms) {
      const bool seen = std::any_of(d.frames.begin(), d.frames.end(), [&](int f) {
        return std::find(p.frames.begin(), p.frames.end(), f) != p.frames.end();
      });
      if (!seen) continue;
      char text[64];
      std::snprintf(text, sizeof text, "%s at station %.3f m", d.kind == "end_wall" ? "the end wall" : "a plate",
                    d.station_m);
      seen_plates.push_back(text);
    }
    for (std::size_t i = 0; i < seen_plates.size(); ++i)
      p.message += (i == 0 ? "; its frames saw " : " and ") + seen_plates[i];
  }
}

}  // namespace

StationMap StationMapBuilder::finish(const std::vector<int>& pose_groups) const {
  const auto t0 = std::chrono::steady_clock::now();
  StationMap out;
  out.options = options_;
  // A straight line is the first frame's axis through its camera (also when no frame was detected).
  const CentrelineFrame zero = have_line_ ? line_.frame_at(0.0) : CentrelineFrame{0.0, origin_, axis_, up_};
  out.origin = zero.point;
  out.axis = zero.axis;
  out.up = zero.up;
  out.line = line_;
  out.frames = static_cast<int>(scans_.size());
  out.poses = merge_scans(scans_, pose_groups, options_.zone_gap_m).poses;
  for (const ScanInput& s : scans_) out.frames_used += s.map.detected ? 1 : 0;
  if (pieces_.empty()) {
    out.status = "no_detection";
    out.reason = "no frame measured a wall of the tunnel; every pose needs a rescan";
    return out;
  }
  const int k0 = pieces_.begin()->first, k1 = pieces_.rbegin()->first;
  const std::vector<WallProfile> prof = profile(pieces_, k0, k1);
  const std::size_t n = prof.size();
  std::vector<double> w(n), h(n);
  for (std::size_t k = 0; k < n; ++k) {
    // Each frame's own dimensions first (drift in the poses cannot make them differ); the
    // pooled wall positions where no frame saw both walls of a pair at the station.
    const Dims d = options_.per_frame_sizes ? station_dims(k0 + static_cast<int>(k)) : Dims{kNaN, kNaN, 0, 0};
    w[k] = !std::isnan(d.width_m) ? d.width_m : prof[k].wall_m[0] + prof[k].wall_m[1];
    h[k] = !std::isnan(d.height_m) ? d.height_m : prof[k].wall_m[2] + prof[k].wall_m[3];
  }
  const double step = options_.station_step_m;
  JointEvidence evidence;
  evidence.views = frame_views(k0);
  evidence.pose_groups = pose_groups;
  evidence.change_m = options_.section_change_mm / 1000.0;
  for (const WallProfile& p : prof) evidence.wall_m.push_back({p.wall_m[0], p.wall_m[1], p.wall_m[2], p.wall_m[3]});
  for (double s : transverse_plate_stations(plates_))
    evidence.plate_stations.push_back(static_cast<int>(std::floor(s / step)) - k0);
  const SectionSplit split = keep_confirmed_joints(
      split_sections(w, h, evidence.change_m, options_.min_section_stations), w, h, evidence);
  const auto deviation = [](double v, const std::optional<double>& design) -> std::optional<double> {
    if (!design || std::isnan(v)) return std::nullopt;
    return (v - *design) * 1000.0;
  };
  std::vector<std::array<double, 4>> section_walls;  // per section: its walls' median positions
  for (const SectionRun& run : split.sections) {
    // Section: bounds at its stations' bin edges; frames that measured any of its stations.
    Section sec;
    sec.from_m = (k0 + run.first) * step;
    sec.to_m = (k0 + run.last + 1) * step;
    sec.width_m = !std::isnan(run.width_m) ? run.width_m : options_.design_width_m.value_or(kNaN);
    sec.height_m = !std::isnan(run.height_m) ? run.height_m : options_.design_height_m.value_or(kNaN);
    std::vector<int> frames;
    double wall_pos[4];
    for (int c = 0; c < 4; ++c) {
      std::vector<double> v;
      for (int k = run.first; k <= run.last; ++k)
        if (!split.outlier[static_cast<std::size_t>(k)] && !std::isnan(prof[k].wall_m[c]))
          v.push_back(prof[k].wall_m[c]);
      wall_pos[c] = median_of_measured(v);
    }
    for (int a : {0, 2}) {  // a wall the section never showed: from the other and the dimension
      const double dim = a == 0 ? sec.width_m : sec.height_m;
      for (int c : {a, a + 1})
        if (std::isnan(wall_pos[c]) && !std::isnan(wall_pos[c ^ 1]) && !std::isnan(dim))
          wall_pos[c] = dim - wall_pos[c ^ 1];
    }
    for (auto it = pieces_.lower_bound(k0 + run.first);
         it != pieces_.end() && it->first <= k0 + run.last; ++it)
      for (const Piece& p : it->second) frames.push_back(p.frame);
    std::sort(frames.begin(), frames.end());
    sec.frames = static_cast<int>(std::unique(frames.begin(), frames.end()) - frames.begin());
    // A seen step lies within one station of its first; an unseen one anywhere in its stretch.
    sec.joint_seen = run.unseen_joint_stations < 0;
    sec.joint_uncertainty_m = sec.joint_seen ? step : 0.5 * (run.unseen_joint_stations + 1) * step;
    out.sections.push_back(sec);
    section_walls.push_back({wall_pos[0], wall_pos[1], wall_pos[2], wall_pos[3]});

    for (int k = run.first; k <= run.last; ++k) {
      Station st;
      st.station_m = (k0 + k + 0.5) * step;
      st.frames = prof[k].frames;
      const bool rejected = split.outlier[static_cast<std::size_t>(k)];
      for (int c = 0; c < 4; ++c) st.wall_m[c] = rejected ? kNaN : prof[k].wall_m[c];
      // Measured here; else the section's value (the context of the stations around);
      // else the design; else unseen.
      const auto fill = [&](double measured, double section, const std::optional<double>& design,
                            double& value, DimensionSource& source) {
        if (!rejected && !std::isnan(measured))
          value = measured, source = DimensionSource::Measured;
        else if (!std::isnan(section))
          value = section, source = DimensionSource::Context;
        else if (design)
          value = *design, source = DimensionSource::Design;
      };
      fill(w[k], run.width_m, options_.design_width_m, st.width_m, st.width_source);
      fill(h[k], run.height_m, options_.design_height_m, st.height_m, st.height_source);
      // A deviation only of a measured or context value: the design is never "0.0 mm off" itself.
      const auto assessed = [](DimensionSource s) {
        return s == DimensionSource::Measured || s == DimensionSource::Context;
      };
      if (assessed(st.width_source)) st.width_dev_mm = deviation(st.width_m, options_.design_width_m);
      if (assessed(st.height_source)) st.height_dev_mm = deviation(st.height_m, options_.design_height_m);
      const auto off = [&](const std::optional<double>& dev, DimensionSource src) {
        return dev && src != DimensionSource::Design && std::abs(*dev) > options_.tolerance_mm;
      };
      st.out_of_tolerance = off(st.width_dev_mm, st.width_source) ||
                            off(st.height_dev_mm, st.height_source);
      out.stations.push_back(st);
    }
  }
  out.ok = true;
  out.status = "ok";
  out.girder = build_girder_structure(out, plates_, {}, range_cut_plates_);
  if (trim_beyond_end_walls(out, section_walls)) out.girder = build_girder_structure(out, plates_, {}, range_cut_plates_);
  note_plates_seen(out);
  for (std::size_t i = 0; i < out.sections.size(); ++i)
    add_section_maps(line_, section_walls[i].data(), out.sections[i].from_m, out.sections[i].to_m,
                     tunnel_.forbidden_band_m, out.section_maps);
  out.timings_ms["map"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace tunnelmap
