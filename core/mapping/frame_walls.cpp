#include "core/mapping/frame_walls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "core/mapping/plate_rims.h"
#include "core/mapping/station_sections.h"
#include "core/tunnel/zone_clustering.h"

namespace tunnelmap {

namespace {

// Zone clusters of the planes among `members` on wall `c`: the outermost supported cluster's
// position (NaN: none), and whether it is the only supported one.
struct Outer {
  double position = std::numeric_limits<double>::quiet_NaN();
  bool single = false;
};

Outer outer_surface(const std::vector<WallSample>& samples, const std::vector<std::size_t>& members,
                    const Eigen::Vector3d& n, const FrameWallsOptions& o, int min_points,
                    std::map<int, std::pair<double, int>>& planes) {
  planes.clear();
  for (std::size_t i : members) {
    auto& p = planes[samples[i].plane];
    p.first += -n.dot(samples[i].point.cast<double>()) * samples[i].points;
    p.second += samples[i].points;
  }
  std::vector<ZonePosition> positions;
  for (const auto& [id, p] : planes) positions.push_back({p.first / p.second, p.second});
  std::vector<ZoneCluster> clusters;
  cluster_zone_positions(positions, o.zone_gap_m, min_points, clusters);
  Outer out;
  const int best = outermost_supported_cluster(clusters, min_points);
  if (best >= 0) {
    out.position = clusters[best].offset_m;
    out.single = single_supported_zone(clusters, min_points);
  }
  return out;
}

// The insets, part by part: the frame's own stations (along its own axis) split where its
// cross-section changes, then per part and wall the detector's zone rule (outermost supported
// cluster; a lone cluster is the middle plate when the frame's wall took a step for it).
void local_insets(const TunnelMap& m, const FrameWallsOptions& o, std::vector<WallSample>& samples) {
  std::map<int, std::array<std::vector<std::size_t>, 4>> stations;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].wall >= 4) continue;
    const int station = static_cast<int>(
        std::floor(m.axis_dir.dot(samples[i].point.cast<double>()) / o.station_m));
    stations[station][samples[i].wall].push_back(i);
  }
  if (stations.empty()) return;
  const int k0 = stations.begin()->first, k1 = stations.rbegin()->first;
  std::vector<double> w(static_cast<std::size_t>(k1 - k0 + 1), NAN), h(w.size(), NAN);
  std::map<int, std::pair<double, int>> planes;
  for (const auto& [k, walls] : stations) {
    double pos[4];
    for (int c = 0; c < 4; ++c)
      pos[c] = outer_surface(samples, walls[c], m.walls[c].normal, o, o.min_zone_points, planes).position;
    // Far stations are seen at grazing angles through coarse depth steps: they do not decide
    // where the cross-section changes.
    if ((k + 0.5) * o.station_m > o.max_split_distance_m) continue;
    w[static_cast<std::size_t>(k - k0)] = pos[0] + pos[1];
    h[static_cast<std::size_t>(k - k0)] = pos[2] + pos[3];
  }
  const SectionSplit split = split_sections(w, h, o.section_change_m, o.min_section_stations);
  if (split.sections.size() == 1) {
    // One cross-section in view: the detector's own wall surfaces (its zone rule over the whole
    // frame, the symmetric step included) are the best reference.
    for (int c = 0; c < 4; ++c) {
      std::vector<std::size_t> members;
      for (const auto& [k, walls] : stations) members.insert(members.end(), walls[c].begin(), walls[c].end());
      if (members.empty()) continue;
      outer_surface(samples, members, m.walls[c].normal, o, o.min_part_points, planes);
      for (std::size_t i : members) {
        const auto& p = planes[samples[i].plane];
        const double inset = m.walls[c].offset_m - p.first / p.second;
        samples[i].on_surface = inset >= -o.zone_gap_m && inset <= o.max_inset_m;
        samples[i].inside = inset > o.max_inset_m;
        samples[i].inset_m = samples[i].on_surface ? static_cast<float>(std::max(0.0, inset)) : 0.0f;
      }
    }
    return;
  }
  for (std::size_t r = 0; r < split.sections.size(); ++r)
    for (int c = 0; c < 4; ++c) {
      const SectionRun& run = split.sections[r];
      std::vector<std::size_t> members;
      for (auto it = stations.lower_bound(k0 + run.first); it != stations.end() && it->first <= k0 + run.last; ++it)
        members.insert(members.end(), it->second[c].begin(), it->second[c].end());
      if (members.empty()) continue;
      const Outer outer = outer_surface(samples, members, m.walls[c].normal, o, o.min_part_points, planes);
      const double step = outer.single ? m.walls[c].symmetric_step_m : 0.0;
      for (std::size_t i : members) {
        const auto& p = planes[samples[i].plane];
        const double inset = std::isnan(outer.position) ? -1.0 : outer.position + step - p.first / p.second;
        samples[i].on_surface = inset >= -o.zone_gap_m && inset <= o.max_inset_m;
        samples[i].inside = inset > o.max_inset_m;
        samples[i].inset_m = samples[i].on_surface ? static_cast<float>(std::max(0.0, inset)) : 0.0f;
        samples[i].part = static_cast<std::uint8_t>(std::min<std::size_t>(r, 255));
      }
    }
}

}  // namespace

void extract_frame_walls(const FrameResult& r, FrameWalls& out, const FrameWallsOptions& o) {
  const int block = o.block_px, min_transverse = o.min_transverse_points;
  out.samples.clear();
  out.rims.clear();
  const TunnelMap& m = r.map;
  const PlaneSegments& ps = r.planes;
  if (ps.labels.empty() || r.cloud.points.size() != ps.labels.size()) return;
  const bool plates_only = !m.detected;
  // Plane id -> sample kind and inset.
  struct Kind {
    std::uint8_t wall;
    float inset;
  };
  std::unordered_map<int, Kind> kind;
  const double cos_transverse = std::cos(kTransverseMaxAngleDeg * M_PI / 180.0);
  for (std::size_t i = 0; i < ps.planes.size() && i < m.plane_classes.size(); ++i) {
    const PlaneSegment& p = ps.planes[i];
    if (p.edge_on) continue;
    const WallClass c = m.plane_classes[i];
    if (c != WallClass::Unassigned) {
      if (plates_only) continue;
      const Wall& w = m.wall(c);
      if (!w.found || w.source != DimensionSource::Measured) continue;
      kind[p.id] = {static_cast<std::uint8_t>(c), 0.0f};
    } else if (std::abs(p.normal.dot(m.axis_dir)) > cos_transverse && p.points >= min_transverse) {
      kind[p.id] = {kTransverseSample, 0.0f};
    }
  }
  if (kind.empty()) return;
  const int W = ps.width, H = ps.height;
  std::unordered_map<int, WallSample> cell;  // plane id -> sums within the current block
  for (int by = 0; by < H; by += block)
    for (int bx = 0; bx < W; bx += block) {
      cell.clear();
      for (int v = by; v < std::min(H, by + block); ++v)
        for (int u = bx; u < std::min(W, bx + block); ++u) {
          const std::size_t i = static_cast<std::size_t>(v) * W + u;
          const int label = ps.labels[i];
          if (label <= 0) continue;
          const auto it = kind.find(label);
          if (it == kind.end()) continue;
          const Eigen::Vector3f& p = r.cloud.points[i];
          if (!OrganizedCloud::valid(p)) continue;
          WallSample& s = cell[label];
          s.point += p;
          ++s.points;
          s.plane = label;
          s.wall = it->second.wall;
          s.inset_m = it->second.inset;
        }
      for (auto& [label, s] : cell) {
        s.point /= static_cast<float>(s.points);
        out.samples.push_back(s);
      }
    }
  if (!plates_only) local_insets(m, o, out.samples);
  std::vector<int> plates;
  for (const auto& [id, k] : kind)
    if (k.wall == kTransverseSample) plates.push_back(id);
  std::sort(plates.begin(), plates.end());
  extract_plate_rims(r, plates, o, out.rims);
}

}  // namespace tunnelmap
