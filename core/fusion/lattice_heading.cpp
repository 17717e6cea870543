#include "core/fusion/lattice_heading.h"

#include <cmath>
#include <Eigen/Eigenvalues>
#include <optional>

namespace tunnelmap {

namespace {

constexpr double kDeg = M_PI / 180.0;

// The horizontal direction of largest spread of the frames' centre points, and that spread
// (max - min along it); nullopt with fewer than two detected frames.
std::optional<Eigen::Vector2d> centre_line_direction(const std::vector<PosedMap>& frames, double* span_m) {
  std::vector<Eigen::Vector2d> pts;
  for (const PosedMap& f : frames) {
    if (!f.map || !f.map->detected) continue;
    const TunnelMap& m = *f.map;
    const Eigen::Vector3d mid = m.axis_point + 0.5 * (m.extent_min_m + m.extent_max_m) * m.axis_dir;
    pts.push_back((f.camera_to_world * mid).head<2>());
  }
  if (pts.size() < 2) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(pts.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov);
  const Eigen::Vector2d dir = es.eigenvectors().col(1);
  double lo = 0.0, hi = 0.0;
  for (const auto& p : pts) {
    const double s = dir.dot(p - mean);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  *span_m = hi - lo;
  return dir;
}

// The yaw's part off the nearest world axis (within +-45 deg): a lattice turned by it has the
// same planes as one turned by the whole heading.
double off_axis(double heading) {
  const double quarter = M_PI / 2;
  return heading - quarter * std::round(heading / quarter);
}

LatticeHeading turned(double yaw, double snap, HeadingSource source) {
  LatticeHeading h;
  h.source = source;
  if (std::abs(yaw) < snap) return h;
  h.lattice_to_world = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  h.yaw_deg = yaw / kDeg;
  return h;
}

}  // namespace

const char* heading_source_name(HeadingSource s) {
  switch (s) {
    case HeadingSource::CentreLine: return "centre_line";
    case HeadingSource::MergedAxis: return "merged_axis";
    case HeadingSource::World: break;
  }
  return "world";
}

LatticeHeading lattice_heading(const std::vector<PosedMap>& frames, const TunnelMap& merged,
                               const Eigen::Vector3d& world_up) {
  if (!merged.detected || std::abs(world_up.normalized().z()) < 0.999) return {};
  double span = 0.0;
  const std::optional<Eigen::Vector2d> dir = centre_line_direction(frames, &span);
  if (dir && span >= kCentreLineBaselineM)
    return turned(off_axis(std::atan2(dir->y(), dir->x())), 0.01 * kDeg, HeadingSource::CentreLine);
  return turned(off_axis(std::atan2(merged.axis_dir.y(), merged.axis_dir.x())), 1.0 * kDeg,
                HeadingSource::MergedAxis);
}

}  // namespace tunnelmap
