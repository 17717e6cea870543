// detect_tunnel: runs the steps of paper section 2.2 in order (see docs/tunnel-detection.md).
// Each step lives in its own file; this one wires them and reports the first failure.
#include "core/tunnel/tunnel_detector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/tunnel/normal_outliers.h"
#include "core/tunnel/template_fit.h"
#include "core/tunnel/tunnel_scratch.h"
#include "core/tunnel/wall_classification.h"
#include "core/tunnel/wall_geometry.h"
#include "core/tunnel/zone_clustering.h"
#include "core/util/error.h"

namespace tunnelmap {

namespace {

constexpr WallClass kWalls[] = {WallClass::Left, WallClass::Right, WallClass::Top,
                                WallClass::Bottom};

// Strings are written into the map's own (reused) buffers: a std::string returned by value
// would allocate on every frame once longer than 15 characters.
[[gnu::format(printf, 2, 3)]] void set_text(std::string& out, const char* f, ...) {
  char buf[256];
  va_list args;
  va_start(args, f);
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  out.assign(buf);
}

[[gnu::format(printf, 2, 3)]] void append_text(std::string& out, const char* f, ...) {
  char buf[256];
  va_list args;
  va_start(args, f);
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  out.append(buf);
}

// The caller writes map.reason.
void fail(TunnelMap& map, TunnelStatus status) {
  map.detected = false;
  map.status = status;
}

// Gives `map` the values of a default TunnelMap while keeping its vectors' and strings'
// buffers (a fresh map would allocate them again). Timings keep the "tunnel" entry, zeroed.
void reset_keeping_buffers(TunnelMap& map) {
  TunnelMap fresh;
  // After the swap `old` holds the default value; copying it back keeps `keep`'s buffer.
  const auto recycle = [](auto& keep, auto& old) {
    keep.swap(old);
    keep = old;
  };
  recycle(fresh.reason, map.reason);
  recycle(fresh.plane_classes, map.plane_classes);
  recycle(fresh.plane_outlier, map.plane_outlier);
  recycle(fresh.plane_candidate_classes, map.plane_candidate_classes);
  recycle(fresh.parts, map.parts);
  for (size_t i = 0; i < fresh.walls.size(); ++i) {
    recycle(fresh.walls[i].clusters, map.walls[i].clusters);
    recycle(fresh.walls[i].zones, map.walls[i].zones);
  }
  fresh.timings_ms.swap(map.timings_ms);
  for (auto it = fresh.timings_ms.begin(); it != fresh.timings_ms.end();) {
    if (it->first == "tunnel") {
      it->second = 0.0;
      ++it;
    } else {
      it = fresh.timings_ms.erase(it);
    }
  }
  map = std::move(fresh);
}

void check_options(const TunnelOptions& o) {
  if (!(o.outlier_bin_deg > 0) || !(o.outlier_max_deg > 0) || !(o.class_angle_deg > 0) ||
      o.class_angle_deg > 45.0 || !(o.zone_cluster_m > 0) || !(o.max_pair_angle_deg > 0) ||
      !(o.forbidden_band_m >= 0) || !(o.max_symmetric_step_m >= 0))
    throw ParameterError("tunnel options out of range (angles and gaps must be > 0, class cone <= 45 deg)");
}

// A plate across the axis (a diaphragm): its plane and the box its outline covers in the image,
// in normalised image coordinates (x/z, y/z).
struct Plate {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double offset = 0, x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  // `q` lies more than 0.1 m behind the plate, on a sight line through the plate's outline: a
  // wall seen through the plate's manhole, in the next bay.
  bool hides(const Eigen::Vector3d& q) const {
    if (!(q.z() > 0) || normal.dot(q) + offset > -0.1) return false;
    const double x = q.x() / q.z(), y = q.y() / q.z();
    return x > x0 && x < x1 && y > y0 && y < y1;
  }
};
constexpr int kMaxPlates = 4;

// The largest plates across the axis: unclassified planes facing along it within the class
// angle, with a zone's support and at least a quarter of the smallest cross-section the
// template allows (a joint between two sections is a ring a few centimetres wide, seen past,
// not through), with an outline. Returns how many (at most kMaxPlates).
int plates_across(const PlaneSegments& planes, const TunnelMap& map, const Eigen::Vector3d& axis,
                  const TunnelOptions& opt, std::array<Plate, kMaxPlates>& out) {
  const double cos_class = std::cos(opt.class_angle_deg * M_PI / 180.0);
  const double min_area = 0.25 * opt.width_min_m * opt.height_min_m;
  std::array<double, kMaxPlates> area{};
  int count = 0;
  for (size_t i = 0; i < planes.planes.size(); ++i) {
    const PlaneSegment& p = planes.planes[i];
    if (map.plane_classes[i] != WallClass::Unassigned || p.edge_on || p.points < opt.min_cluster_points ||
        p.area_m2 < min_area || p.contour.empty() || std::abs(p.normal.dot(axis)) < cos_class)
      continue;
    int k = kMaxPlates - 1;  // when full, the smallest gives way to a larger one
    if (count < kMaxPlates) {
      k = count++;
    } else if (area[k] >= p.area_m2) {
      continue;
    }
    for (; k > 0 && area[k - 1] < p.area_m2; --k) area[k] = area[k - 1], out[k] = out[k - 1];
    Plate& plate = out[k];
    area[k] = p.area_m2;
    plate.normal = p.normal, plate.offset = p.offset_m;
    plate.x0 = plate.y0 = std::numeric_limits<double>::infinity();
    plate.x1 = plate.y1 = -plate.x0;
    for (const auto& q : p.contour) {
      if (!(q.z() > 0)) continue;
      plate.x0 = std::min(plate.x0, q.x() / q.z()), plate.x1 = std::max(plate.x1, q.x() / q.z());
      plate.y0 = std::min(plate.y0, q.y() / q.z()), plate.y1 = std::max(plate.y1, q.y() / q.z());
    }
  }
  return count;
}

// Steps 1-2: classes, outliers and per-class mean normals. seen[c]: the class kept a plane.
// map.reason lists the classes without planes (read only if too few walls remain).
void classify_and_reject(const PlaneSegments& planes, const RoughTunnelFrame& rough,
                         const TunnelOptions& opt, TunnelMap& map, TunnelScratch& scr,
                         Eigen::Vector3d means[4], bool seen[4], double support[4]) {
  const size_t n = planes.planes.size();
  classify_planes(rough, planes, opt.class_angle_deg, map.plane_candidate_classes);
  map.plane_classes = map.plane_candidate_classes;  // copy-assignment reuses the buffer
  map.plane_outlier.assign(n, false);
  std::string& missing = map.reason;
  missing.clear();
  for (WallClass c : kWalls) {
    std::vector<size_t>& members = scr.members;
    std::vector<WeightedNormal>& normals = scr.normals;
    members.clear();
    normals.clear();
    for (size_t i = 0; i < n; ++i) {
      if (map.plane_candidate_classes[i] != c) continue;
      members.push_back(i);
      normals.push_back({planes.planes[i].normal.normalized(),
                         static_cast<double>(std::max(1, planes.planes[i].points))});
    }
    NormalClassStats& st = scr.stats;
    reject_normal_outliers(normals, opt.outlier_bin_deg, opt.outlier_max_deg, st, scr.outliers);
    Wall& w = map.wall(c);
    w.cls = c;
    support[static_cast<int>(c)] = 0.0;
    for (size_t k = 0; k < members.size(); ++k) {
      if (st.inlier[k]) {
        ++w.inlier_planes;
        support[static_cast<int>(c)] += normals[k].weight;
      } else {
        ++w.outlier_planes;
        map.plane_outlier[members[k]] = true;
        map.plane_classes[members[k]] = WallClass::Unassigned;
      }
    }
    w.normal_sd_deg = st.sd_deg;
    means[static_cast<int>(c)] = st.mean;
    seen[static_cast<int>(c)] = st.valid;
    if (!st.valid) {
      if (!missing.empty()) missing += "; ";
      append_text(missing, "%s wall: %zu planes%s", wall_class_name(c), members.size(),
                  members.empty() ? "" : ", all outliers");
    }
  }
}

int count(const bool v[4]) { return int(v[0]) + int(v[1]) + int(v[2]) + int(v[3]); }

// A dimension whose pair was not fully measured: the design infers the missing wall from the
// one seen (or gives the dimension alone when neither was); otherwise it stays unseen.
void infer_from_design(const bool measured[4], int a, int b, double design_m, double offsets[4],
                       DimensionSource& source, double& value, TunnelMap& map) {
  if (measured[a] && measured[b]) {
    source = DimensionSource::Measured;
    value = offsets[a] + offsets[b];
    return;
  }
  if (!(design_m > 0)) return;
  source = DimensionSource::Design;
  value = design_m;
  for (const auto& [seen_wall, missing_wall] : {std::pair{a, b}, std::pair{b, a}}) {
    if (!measured[seen_wall] || measured[missing_wall]) continue;
    offsets[missing_wall] = design_m - offsets[seen_wall];
    map.walls[missing_wall].found = true;
    map.walls[missing_wall].source = DimensionSource::Design;
    map.walls[missing_wall].offset_m = offsets[missing_wall];
  }
}

}  // namespace

void describe_tunnel_map(TunnelMap& map) {
  if (map.status == TunnelStatus::Ok) {
    set_text(map.reason, "width %.3f m, height %.3f m", map.width_m, map.height_m);
    return;
  }
  map.reason.clear();
  const std::pair<const char*, DimensionSource> dims[] = {{"width", map.width_source},
                                                          {"height", map.height_source}};
  for (const auto& [name, src] : dims) {  // what was not measured: "height from context"
    if (src == DimensionSource::Measured) continue;
    if (!map.reason.empty()) map.reason += ", ";
    if (src == DimensionSource::Unseen)
      append_text(map.reason, "%s unknown", name);
    else
      append_text(map.reason, "%s from %s", name, dimension_source_name(src));
  }
}

namespace {

void run(const PlaneSegments& planes, const Eigen::Vector3d& up_camera, const TunnelOptions& opt,
         const TunnelContext* context, TunnelMap& map, TunnelScratch& scratch) {
  const size_t n = planes.planes.size();
  map.plane_classes.assign(n, WallClass::Unassigned);
  map.plane_candidate_classes.assign(n, WallClass::Unassigned);
  map.plane_outlier.assign(n, false);
  for (WallClass c : kWalls) map.wall(c).cls = c;
  const RoughTunnelFrame rough = make_rough_frame(up_camera);
  map.up = rough.up;
  map.axis_dir = rough.forward;

  if (n < 2) {
    fail(map, TunnelStatus::TooFewPlanes);
    set_text(map.reason, "%.0f planes detected, at least 2 needed", double(n));
    return;
  }

  // Steps 1-2. Two walls at least: one or two may be out of view (e.g. the floor near a
  // manhole plate) and the map is then partial.
  Eigen::Vector3d means[4];
  bool seen[4];
  double support[4];
  classify_and_reject(planes, rough, opt, map, scratch, means, seen, support);
  // A pair that is not parallel, one of whose walls has far fewer points than the other: the
  // weak one is taken as not seen (e.g. the floor near a manhole plate, where what is left of
  // it is a sliver of something else), as long as two walls remain; the map is then partial.
  // Two well-supported walls that are not parallel stay "no_parallel_pair".
  for (int a : {0, 2}) {
    if (!seen[a] || !seen[a + 1] || count(seen) <= 2) continue;
    if (angle_deg(means[a], -means[a + 1]) <= opt.max_pair_angle_deg) continue;
    const int weaker = support[a] < support[a + 1] ? a : a + 1;
    if (support[weaker] > 0.25 * support[weaker ^ 1]) continue;
    seen[weaker] = false;
    for (size_t i = 0; i < n; ++i)
      if (map.plane_classes[i] == static_cast<WallClass>(weaker))
        map.plane_classes[i] = WallClass::Unassigned;
  }
  if (count(seen) < 2) {
    fail(map, TunnelStatus::MissingWall);
    return;
  }

  // Step 3: rectangular template.
  TemplateFrame& tf = scratch.frame;
  fit_partial_template(means, seen, rough.right, rough.up, rough.forward, opt.max_pair_angle_deg,
                       tf, support);
  if (!tf.ok) {
    map.detected = false;
    map.status = tf.status;
    map.reason = tf.reason;  // copy-assignment reuses the map's buffer
    return;
  }
  const Eigen::Vector3d template_normal[4] = {tf.right, -tf.right, -tf.up, tf.up};

  // Step 4: zone positions with the common wall normal, clustered; outermost supported zone.
  // Support and gap may scale with each zone's distance from the camera (zone_support.h).
  ZoneScaling zone_scaling;
  zone_scaling.min_points = opt.min_cluster_points;
  zone_scaling.support_ref_m = opt.zone_support_ref_m;
  zone_scaling.gap_m = opt.zone_cluster_m;
  zone_scaling.gap_ref_m = opt.zone_gap_ref_m;
  check_zone_scaling(zone_scaling);
  double offsets[4] = {0, 0, 0, 0};
  bool measured[4] = {false, false, false, false};
  // Visible span across the tunnel of every classified plane: bounds the rectangles of the
  // walls that were not measured (they are drawn only where the measured walls were seen).
  double span[4] = {0, 0, 0, 0};
  std::string weak;  // walls seen without a supported zone (small: no allocation)
  std::vector<ZonePosition>& positions = scratch.positions;
  double axial_min = std::numeric_limits<double>::infinity();
  double axial_max = -axial_min;
  std::array<Plate, kMaxPlates> plates;
  const int plate_count = plates_across(planes, map, tf.axis, opt, plates);
  for (WallClass c : kWalls) {
    const int ci = static_cast<int>(c);
    Wall& w = map.wall(c);
    w.normal = template_normal[ci];
    positions.clear();
    for (size_t i = 0; i < n; ++i) {
      if (map.plane_classes[i] != c) continue;
      const PlaneSegment& p = planes.planes[i];
      const auto extend = [&](const Eigen::Vector3d& q) {
        axial_min = std::min(axial_min, tf.axis.dot(q));
        axial_max = std::max(axial_max, tf.axis.dot(q));
        for (int k = 0; k < 4; ++k) span[k] = std::max(span[k], -template_normal[k].dot(q));
      };
      // Behind a plate: the next bay, seen through its manhole (a sliver of floor 3 m away,
      // whose position the frame's smallest angular error moves by centimetres).
      bool hidden = false;
      for (int k = 0; k < plate_count && !hidden; ++k) hidden = plates[k].hides(p.centroid);
      if (hidden) continue;
      // Planes seen nearly edge-on (the edge-on pass of coarse-to-fine growing) measure no zone
      // and bound no extent: their normals are the noisiest and they straddle plates a few
      // millimetres apart. With them, field height sigma rose from 0.15 to 1.2 mm
      // (docs/method.md).
      if (p.edge_on) continue;
      if (p.contour.empty()) extend(p.centroid);
      for (const auto& q : p.contour) extend(q);
      positions.push_back({-w.normal.dot(p.centroid), p.points});
    }
    if (!seen[ci]) continue;
    cluster_zone_positions(positions, zone_scaling, w.clusters, scratch.zones);
    const int best = outermost_supported_cluster(w.clusters, zone_scaling);
    if (best < 0) {
      if (!weak.empty()) weak += "; ";
      if (zone_scaling.support_ref_m > 0) {  // the support asked for depends on the distance
        const ZoneCluster* largest = nullptr;
        for (const ZoneCluster& z : w.clusters)
          if (!largest || z.points > largest->points) largest = &z;
        append_text(weak,
                    "%s wall: no zone cluster with enough points (largest %d at %.2f m, needs %d)",
                    wall_class_name(c), largest ? largest->points : 0,
                    largest ? largest->offset_m : 0.0,
                    largest ? zone_scaling.support_at(largest->offset_m) : opt.min_cluster_points);
      } else {
        append_text(weak, "%s wall: no zone cluster with >= %d points", wall_class_name(c),
                    opt.min_cluster_points);
      }
      continue;
    }
    measured[ci] = true;
    w.found = true;
    w.source = DimensionSource::Measured;
    offsets[ci] = w.clusters[best].offset_m;
    w.offset_m = offsets[ci];
  }
  if (count(measured) < 2) {
    fail(map, TunnelStatus::MissingWall);
    if (!weak.empty()) {
      if (!map.reason.empty()) map.reason += "; ";
      map.reason += weak;
    }
    return;
  }
  if (opt.max_symmetric_step_m > 0) {  // symmetric zone prior, steps first, then applied
    // A wall seen only by its middle plate takes the opposite wall's step, else the mean
    // step of the two perpendicular walls (the rectangular template's other pair).
    const int opposite[4] = {1, 0, 3, 2};
    const int perpendicular[4][2] = {{2, 3}, {2, 3}, {0, 1}, {0, 1}};
    double seen_step[4], step[4] = {0, 0, 0, 0};
    for (WallClass c : kWalls)
      seen_step[int(c)] = measured[int(c)] ? observed_edge_step(map.wall(c).clusters,
                                                                opt.min_cluster_points,
                                                                opt.max_symmetric_step_m)
                                           : 0.0;
    for (WallClass c : kWalls) {
      const int ci = int(c);
      if (!measured[ci] || !single_supported_zone(map.wall(c).clusters, opt.min_cluster_points))
        continue;
      if (seen_step[opposite[ci]] > 0) {
        step[ci] = seen_step[opposite[ci]];
      } else {
        const double a = seen_step[perpendicular[ci][0]], b = seen_step[perpendicular[ci][1]];
        const int k = (a > 0) + (b > 0);
        step[ci] = k ? (a + b) / k : 0.0;
      }
    }
    for (WallClass c : kWalls) {
      if (!measured[int(c)]) continue;
      offsets[int(c)] += step[int(c)];
      map.wall(c).offset_m = offsets[int(c)];
      map.wall(c).symmetric_step_m = step[int(c)];
    }
  }
  infer_from_design(measured, 0, 1, opt.design_width_m, offsets, map.width_source, map.width_m, map);
  infer_from_design(measured, 2, 3, opt.design_height_m, offsets, map.height_source, map.height_m,
                    map);
  // A design never makes a tunnel by itself: the frame must measure at least one dimension.
  if (map.width_source != DimensionSource::Measured && map.height_source != DimensionSource::Measured) {
    fail(map, TunnelStatus::MissingWall);
    set_text(map.reason, "neither the width nor the height was measured (walls seen: %s%s%s%s)",
             measured[0] ? "left " : "", measured[1] ? "right " : "", measured[2] ? "top " : "",
             measured[3] ? "bottom" : "");
    return;
  }

  // Step 6 (done before the checks so a rejected map can still be inspected). Walls neither
  // measured nor inferred bound the drawing at the visible span and are not part of the map.
  double draw[4];
  for (int k = 0; k < 4; ++k) draw[k] = map.walls[k].found ? offsets[k] : span[k];
  const WallOffsets off{draw[0], draw[1], draw[2], draw[3]};
  build_wall_geometry(tf, off, axial_min, axial_max, opt.forbidden_band_m, map);
  for (Wall& w : map.walls)
    if (!w.found) w.zones.clear();  // offset_m keeps the drawn span (rebuild_wall_geometry)

  // Step 5: template prior and context of earlier scans.
  if (map.width_source == DimensionSource::Measured) {
    if (map.width_m < opt.width_min_m || map.width_m > opt.width_max_m) {
      fail(map, TunnelStatus::OutOfTemplate);
      set_text(map.reason, "width %.3f m outside [%.2f, %.2f]", map.width_m, opt.width_min_m,
               opt.width_max_m);
      return;
    }
  }
  if (map.height_source == DimensionSource::Measured) {
    if (map.height_m < opt.height_min_m || map.height_m > opt.height_max_m) {
      fail(map, TunnelStatus::OutOfTemplate);
      set_text(map.reason, "height %.3f m outside [%.2f, %.2f]", map.height_m, opt.height_min_m,
               opt.height_max_m);
      return;
    }
  }
  map.detected = true;
  map.status = count(measured) == 4 ? TunnelStatus::Ok : TunnelStatus::Partial;
  describe_tunnel_map(map);
  if (context) apply_tunnel_context(map, opt, *context);
}

}  // namespace

TunnelMap detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                        const TunnelOptions& options, const TunnelContext* context) {
  TunnelMap map;
  detect_tunnel(planes, up_camera, options, context, map);
  return map;
}

void detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                   const TunnelOptions& options, const TunnelContext* context, TunnelMap& map) {
  TunnelScratch scratch;
  detect_tunnel(planes, up_camera, options, context, map, scratch);
}

void detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                   const TunnelOptions& options, const TunnelContext* context, TunnelMap& map,
                   TunnelScratch& scratch) {
  const double up_norm = up_camera.norm();
  if (!std::isfinite(up_norm) || up_norm < 1e-9)
    throw ParameterError("tunnel detection: the up vector must be finite and non-zero");
  check_options(options);
  reset_keeping_buffers(map);
  StageTimer timer(map.timings_ms, "tunnel");
  run(planes, up_camera, options, context, map, scratch);
}

void apply_tunnel_context(TunnelMap& map, const TunnelOptions& opt, const TunnelContext& context) {
  if (!map.detected) return;
  // Only what this frame measured is checked: an inferred value agrees by construction.
  const double dw = map.width_measured() && context.has_width() ? map.width_m - context.width_m() : 0.0;
  const double dh =
      map.height_measured() && context.has_height() ? map.height_m - context.height_m() : 0.0;
  if (std::abs(dw) > opt.context_tolerance_m) {
    fail(map, TunnelStatus::InconsistentWithContext);
    set_text(map.reason, "width %.3f m differs from the context's %.3f m by more than %.0f mm",
             map.width_m, context.width_m(), opt.context_tolerance_m * 1000.0);
  } else if (std::abs(dh) > opt.context_tolerance_m) {
    fail(map, TunnelStatus::InconsistentWithContext);
    set_text(map.reason, "height %.3f m differs from the context's %.3f m by more than %.0f mm",
             map.height_m, context.height_m(), opt.context_tolerance_m * 1000.0);
  }
}

}  // namespace tunnelmap
