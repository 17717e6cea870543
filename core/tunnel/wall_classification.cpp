#include "core/tunnel/wall_classification.h"

#include <cmath>

#include <Eigen/Geometry>

namespace tunnelmap {

const char* wall_class_name(WallClass c) {
  switch (c) {
    case WallClass::Left: return "left";
    case WallClass::Right: return "right";
    case WallClass::Top: return "top";
    case WallClass::Bottom: return "bottom";
    case WallClass::Unassigned: return "unassigned";
  }
  return "unassigned";
}

const char* dimension_source_name(DimensionSource s) {
  switch (s) {
    case DimensionSource::Measured: return "measured";
    case DimensionSource::Context: return "context";
    case DimensionSource::Design: return "design";
    case DimensionSource::Unseen: return "unseen";
  }
  return "unseen";
}

RoughTunnelFrame make_rough_frame(const Eigen::Vector3d& up_in) {
  RoughTunnelFrame f;
  f.up = up_in.normalized();
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d fwd = z - z.dot(f.up) * f.up;
  if (fwd.norm() > 1e-6) {
    f.forward = fwd.normalized();
    f.right = f.forward.cross(f.up);
  } else {
    // Camera looks straight up or down the "up" direction: fall back on camera +X as right.
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
    f.right = (x - x.dot(f.up) * f.up).normalized();
    f.forward = f.up.cross(f.right);
  }
  return f;
}

WallClass classify_normal(const RoughTunnelFrame& frame, const Eigen::Vector3d& normal,
                          double class_angle_deg) {
  const double n = normal.norm();
  if (!std::isfinite(n) || n < 1e-12) return WallClass::Unassigned;
  const Eigen::Vector3d u = normal / n;
  const double cos_limit = std::cos(class_angle_deg * M_PI / 180.0);
  // The four class directions are 90 degrees apart and the cone is at most 45 degrees, so at
  // most one can match (ties at exactly 45 go to the first).
  struct Candidate { WallClass cls; Eigen::Vector3d dir; };
  const Candidate candidates[] = {{WallClass::Top, -frame.up},
                                  {WallClass::Bottom, frame.up},
                                  {WallClass::Left, frame.right},
                                  {WallClass::Right, -frame.right}};
  for (const auto& c : candidates)
    if (u.dot(c.dir) >= cos_limit) return c.cls;
  return WallClass::Unassigned;
}

std::vector<WallClass> classify_planes(const RoughTunnelFrame& frame, const PlaneSegments& planes,
                                       double class_angle_deg) {
  std::vector<WallClass> out;
  classify_planes(frame, planes, class_angle_deg, out);
  return out;
}

void classify_planes(const RoughTunnelFrame& frame, const PlaneSegments& planes,
                     double class_angle_deg, std::vector<WallClass>& out) {
  out.clear();
  out.reserve(planes.planes.size());
  for (const auto& p : planes.planes) out.push_back(classify_normal(frame, p.normal, class_angle_deg));
}

}  // namespace tunnelmap
