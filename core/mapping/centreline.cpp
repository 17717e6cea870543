#include "core/mapping/centreline.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap {

Centreline Centreline::straight(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                                const Eigen::Vector3d& up) {
  Centreline c;
  c.nodes_ = {CentrelineFrame{0.0, origin, axis, up}};
  return c;
}

Centreline Centreline::through(std::vector<CentrelineFrame> nodes) {
  Centreline c;
  if (!nodes.empty()) c.nodes_ = std::move(nodes);
  return c;
}

int Centreline::nearest_node(double s) const {
  const auto hi = std::lower_bound(nodes_.begin(), nodes_.end(), s,
                                   [](const CentrelineFrame& f, double v) { return f.station_m < v; });
  if (hi == nodes_.begin()) return 0;
  if (hi == nodes_.end()) return static_cast<int>(nodes_.size()) - 1;
  const auto lo = hi - 1;
  return static_cast<int>((s - lo->station_m <= hi->station_m - s ? lo : hi) - nodes_.begin());
}

LinePosition Centreline::locate(const Eigen::Vector3d& world, int hint) const {
  const int n = static_cast<int>(nodes_.size());
  int i = hint;
  if (i < 0 || i >= n) {  // no hint: the nearest node in space
    i = 0;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < n; ++k)
      if (const double d = (nodes_[k].point - world).squaredNorm(); d < best) best = d, i = k;
  }
  // Each node's frame holds from halfway to the previous node to halfway to the next: walk to
  // the node whose stretch the point's perpendicular falls in. Nodes turn by far less than a
  // degree each, so the walk never turns back (the step bound only guards against that).
  double u = nodes_[i].axis.dot(world - nodes_[i].point);
  for (int steps = 0; steps < n; ++steps) {
    if (i + 1 < n && u >= 0.5 * (nodes_[i + 1].station_m - nodes_[i].station_m)) ++i;
    else if (i > 0 && u < -0.5 * (nodes_[i].station_m - nodes_[i - 1].station_m)) --i;
    else break;
    u = nodes_[i].axis.dot(world - nodes_[i].point);
  }
  const CentrelineFrame& f = nodes_[i];
  const Eigen::Vector3d d = world - f.point;
  return {f.station_m + u, f.left().dot(d), f.up.dot(d), i};
}

CentrelineFrame Centreline::frame_at(double s) const {
  CentrelineFrame f = nodes_[nearest_node(s)];
  f.point += (s - f.station_m) * f.axis;
  f.station_m = s;
  return f;
}

Eigen::Vector3d Centreline::to_world(double s, double lateral, double vertical) const {
  const CentrelineFrame f = frame_at(s);
  return f.point + lateral * f.left() + vertical * f.up;
}

}  // namespace tunnelmap
