#include "core/mapping/frame_walls.h"

#include <cmath>
#include <unordered_map>

namespace tunnelmap {

void extract_frame_walls(const FrameResult& r, FrameWalls& out, int block, int min_transverse) {
  out.samples.clear();
  const TunnelMap& m = r.map;
  const PlaneSegments& ps = r.planes;
  if (!m.detected || ps.labels.empty() || r.cloud.points.size() != ps.labels.size()) return;
  // Plane id -> sample kind and inset.
  struct Kind {
    std::uint8_t wall;
    float inset;
  };
  std::unordered_map<int, Kind> kind;
  const double cos_transverse = std::cos(20.0 * M_PI / 180.0);
  for (std::size_t i = 0; i < ps.planes.size() && i < m.plane_classes.size(); ++i) {
    const PlaneSegment& p = ps.planes[i];
    if (p.edge_on) continue;
    const WallClass c = m.plane_classes[i];
    if (c != WallClass::Unassigned) {
      const Wall& w = m.wall(c);
      if (!w.found || w.source != DimensionSource::Measured) continue;
      const double position = -w.normal.dot(p.centroid);  // along the wall's outward normal
      kind[p.id] = {static_cast<std::uint8_t>(c), static_cast<float>(w.offset_m - position)};
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
}

}  // namespace tunnelmap
