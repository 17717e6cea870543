#include "core/mapping/multi_scan_map.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace tunnelmap {

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// A zone seen by one frame, in the merged wall's coordinates: s along the axis, t across the
// wall (along e = n x axis), h above the wall plane.
struct ZoneObs {
  ZoneKind kind;
  double s0, s1, t0, t1, h;
};

}  // namespace

TunnelMap transform_map(const TunnelMap& in, const Eigen::Isometry3d& T) {
  TunnelMap m = in;
  const Eigen::Matrix3d R = T.linear();
  m.axis_point = T * in.axis_point;
  m.axis_dir = R * in.axis_dir;
  m.up = R * in.up;
  for (Wall& w : m.walls) {
    // n.x + o = 0 in the old frame; x = T^-1 y: (R n).y + (o - (R n).t) = 0.
    const Eigen::Vector3d n = R * w.normal;
    w.offset_m = w.offset_m - n.dot(T.translation());
    for (ZoneCluster& c : w.clusters) c.offset_m = c.offset_m - n.dot(T.translation());
    w.normal = n;
    for (ZoneRect& z : w.zones)
      for (Eigen::Vector3d& p : z.corners) p = T * p;
    for (Eigen::Vector3d& p : w.boundary) p = T * p;
  }
  return m;
}

std::vector<int> group_poses(const std::vector<Eigen::Isometry3d>& poses, double max_move_m,
                             double max_turn_deg) {
  std::vector<int> g(poses.size(), 0);
  std::size_t first = 0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const Eigen::Isometry3d d = poses[first].inverse() * poses[i];
    const double turn = Eigen::AngleAxisd(d.linear()).angle() * 180.0 / M_PI;
    if (d.translation().norm() > max_move_m || turn > max_turn_deg) {
      first = i;
      g[i] = g[i - 1] + 1;
    } else {
      g[i] = g[i - 1];
    }
  }
  return g;
}

MultiScanMap merge_scans(const std::vector<ScanInput>& scans, const std::vector<int>& groups,
                         double zone_gap_m) {
  MultiScanMap out;
  // Pose groups and their rescan verdicts.
  std::map<int, std::size_t> group_slot;
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const int gid = i < groups.size() ? groups[i] : 0;
    if (!group_slot.count(gid)) {
      group_slot[gid] = out.poses.size();
      PoseGroupStatus p;
      p.group = gid;
      p.camera_to_world = scans[i].camera_to_world;
      out.poses.push_back(p);
    }
    PoseGroupStatus& p = out.poses[group_slot[gid]];
    p.frames.push_back(scans[i].frame_index);
    if (scans[i].map.detected) ++p.detected_frames;
  }
  for (PoseGroupStatus& p : out.poses) {
    if (p.detected_frames > 0) {
      p.status = p.message = "ok";
      continue;
    }
    std::map<std::string, int> votes;
    std::string reason;
    for (std::size_t i = 0; i < scans.size(); ++i)
      if ((i < groups.size() ? groups[i] : 0) == p.group) {
        if (++votes[status_name(scans[i].map.status)] >= votes[p.status]) {
          p.status = status_name(scans[i].map.status);
          reason = scans[i].map.reason;
        }
      }
    p.rescan = true;
    p.message = "move and rescan: " + p.status + (reason.empty() ? "" : " (" + reason + ")");
  }

  std::vector<TunnelMap> maps;
  for (const ScanInput& s : scans)
    if (s.map.detected) maps.push_back(transform_map(s.map, s.camera_to_world));
  TunnelMap& m = out.map;
  out.frames_merged = static_cast<int>(maps.size());
  if (maps.empty()) {
    m.detected = false;
    m.status = TunnelStatus::NoDetection;
    m.reason = "no frame found the tunnel; every pose needs a rescan";
    return out;
  }

  // Axis, up, size, centre line.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero(), up = Eigen::Vector3d::Zero();
  std::vector<double> widths, heights;
  for (const TunnelMap& t : maps) {
    axis += t.axis_dir.dot(maps[0].axis_dir) < 0 ? -t.axis_dir : t.axis_dir;
    up += t.up;
    if (t.has_width()) widths.push_back(t.width_m);  // a partial map may leave one unknown
    if (t.has_height()) heights.push_back(t.height_m);
  }
  axis.normalize();
  up = (up - axis * axis.dot(up)).normalized();
  const Eigen::Vector3d left = up.cross(axis);  // right-handed: axis x left = up
  const Eigen::Vector3d origin = maps[0].axis_point;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double s_min = INFINITY, s_max = -INFINITY;
  for (const TunnelMap& t : maps) {
    const Eigen::Vector3d d = t.axis_point - origin;
    centre += d - axis * axis.dot(d);
    for (double e : {t.extent_min_m, t.extent_max_m}) {
      const double s = axis.dot(t.axis_point + e * t.axis_dir - origin);
      s_min = std::min(s_min, s);
      s_max = std::max(s_max, s);
    }
  }
  centre = origin + centre / double(maps.size());
  m.detected = true;
  m.status = TunnelStatus::Ok;
  m.reason = "merged " + std::to_string(maps.size()) + " frames";
  m.width_m = median(widths);
  m.height_m = median(heights);
  m.width_source = widths.empty() ? DimensionSource::Unseen : DimensionSource::Measured;
  m.height_source = heights.empty() ? DimensionSource::Unseen : DimensionSource::Measured;
  const auto spread = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  out.width_spread_m = spread(widths);
  out.height_spread_m = spread(heights);
  m.axis_point = centre;
  m.axis_dir = axis;
  m.up = up;
  m.extent_min_m = s_min;
  m.extent_max_m = s_max;

  for (int c = 0; c < 4; ++c) {
    Wall& w = m.walls[c];
    w.cls = static_cast<WallClass>(c);
    // Inward normals: the left wall (at +left) faces -left, the top (at +up) faces -up.
    const Eigen::Vector3d n = c == 0 ? -left : c == 1 ? left : c == 2 ? -up : up;
    const double half = (c < 2 ? m.width_m : m.height_m) / 2.0;
    const double half_across = (c < 2 ? m.height_m : m.width_m) / 2.0;
    const Eigen::Vector3d w0 = centre - n * half;  // on the wall, level with the centre line
    const Eigen::Vector3d e = n.cross(axis);
    w.normal = n;
    w.offset_m = -n.dot(w0);
    auto at = [&](double s, double t, double h) { return Eigen::Vector3d(w0 + s * axis + t * e + h * n); };

    std::vector<ZoneObs> obs;
    std::vector<std::pair<double, ZoneCluster>> cl;  // (height above the wall, cluster)
    for (const TunnelMap& t : maps) {
      const Wall& fw = t.walls[c];
      if (!fw.found) continue;
      w.found = true;
      w.source = DimensionSource::Measured;
      w.inlier_planes += fw.inlier_planes;
      w.outlier_planes += fw.outlier_planes;
      for (const ZoneCluster& z : fw.clusters) {
        const Eigen::Vector3d p = -z.offset_m * fw.normal;  // a point on the cluster's plane
        cl.push_back({n.dot(p - w0), z});
      }
      for (const ZoneRect& z : fw.zones) {
        ZoneObs o{z.kind, INFINITY, -INFINITY, INFINITY, -INFINITY, 0.0};
        for (const Eigen::Vector3d& p : z.corners) {
          const Eigen::Vector3d d = p - w0;
          o.s0 = std::min(o.s0, axis.dot(d));
          o.s1 = std::max(o.s1, axis.dot(d));
          o.t0 = std::min(o.t0, e.dot(d));
          o.t1 = std::max(o.t1, e.dot(d));
          o.h += n.dot(d) / 4.0;
        }
        obs.push_back(o);
      }
    }
    if (!w.found) continue;
    // Zones: the same zone seen by several frames overlaps across the wall by more than half.
    std::vector<std::vector<ZoneObs>> groups_z;
    for (const ZoneObs& o : obs) {
      bool placed = false;
      for (auto& g : groups_z) {
        const ZoneObs& r = g.front();
        const double overlap = std::min(r.t1, o.t1) - std::max(r.t0, o.t0);
        if (r.kind == o.kind && overlap > 0.5 * std::min(r.t1 - r.t0, o.t1 - o.t0)) {
          g.push_back(o);
          placed = true;
          break;
        }
      }
      if (!placed) groups_z.push_back({o});
    }
    for (const auto& g : groups_z) {
      std::vector<double> t0, t1, h;
      for (const ZoneObs& o : g) {
        t0.push_back(o.t0);
        t1.push_back(o.t1);
        h.push_back(o.h);
      }
      ZoneRect z;
      z.kind = g.front().kind;
      const double a = std::clamp(median(t0), -half_across, half_across);
      const double b = std::clamp(median(t1), -half_across, half_across);
      const double hh = median(h);
      z.corners = {at(s_min, a, hh), at(s_max, a, hh), at(s_max, b, hh), at(s_min, b, hh)};
      w.zones.push_back(z);
    }
    std::sort(w.zones.begin(), w.zones.end(), [&](const ZoneRect& p, const ZoneRect& q) {
      return e.dot(p.corners[0] - w0) < e.dot(q.corners[0] - w0);
    });
    // Zone clusters (plate positions) merged by height above the wall plane.
    std::sort(cl.begin(), cl.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
    for (std::size_t i = 0; i < cl.size();) {
      std::size_t j = i;
      double hs = 0.0;
      ZoneCluster z;
      while (j < cl.size() && cl[j].first - cl[i].first < zone_gap_m) {
        hs += cl[j].first * cl[j].second.points;
        z.planes += cl[j].second.planes;
        z.points += cl[j].second.points;
        ++j;
      }
      const double hmean = z.points > 0 ? hs / z.points : cl[i].first;
      z.offset_m = -n.dot(w0 + hmean * n);
      w.clusters.push_back(z);
      i = j;
    }
    w.boundary = {at(s_min, -half_across, 0), at(s_max, -half_across, 0),
                  at(s_max, half_across, 0), at(s_min, half_across, 0)};
  }
  return out;
}

}  // namespace tunnelmap
