#include "ui/scene/station_grid.h"

#include "ui/scene/label_points.h"

#include <Eigen/Geometry>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tunnelmap::scene {

namespace {
constexpr double kLift_m = 0.02;   // above the wall's points, as the boundary is
constexpr int kMaxStations = 200;  // 100 m at 0.5 m: never more than a long view holds
}  // namespace

StationGrid make_station_grid(const TunnelMap& map, double step_m, int label_every) {
  StationGrid g;
  g.lines = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  LabelPoints labels;
  g.labels = labels.polydata();
  g.lines->SetPoints(points);
  g.lines->SetLines(lines);
  if (!map.detected || !(step_m > 0)) return g;

  const Wall* floor = &map.wall(WallClass::Bottom);
  if (!floor->found) floor = &map.wall(WallClass::Top);
  if (!floor->found || !floor->normal.allFinite()) return g;
  const Eigen::Vector3d axis = map.axis_dir.normalized();
  const Eigen::Vector3d n = floor->normal;
  const Eigen::Vector3d side = n.cross(axis).normalized();
  // The wall's extent across and along the tunnel, from its boundary rectangle.
  double across_lo = std::numeric_limits<double>::infinity(), across_hi = -across_lo;
  double along_lo = across_lo, along_hi = -across_lo;
  for (const auto& c : floor->boundary) {
    if (!c.allFinite()) return g;
    across_lo = std::min(across_lo, c.dot(side));
    across_hi = std::max(across_hi, c.dot(side));
    along_lo = std::min(along_lo, c.dot(axis));
    along_hi = std::max(along_hi, c.dot(axis));
  }
  // Stations are distances ahead of the camera (the origin), whichever way the axis points.
  const double sign = along_hi + along_lo >= 0 ? 1.0 : -1.0;
  const double near = sign > 0 ? along_lo : -along_hi, far = sign > 0 ? along_hi : -along_lo;
  const int first = static_cast<int>(std::ceil(std::max(0.0, near) / step_m));
  const int last = std::min(first + kMaxStations, static_cast<int>(std::floor(far / step_m)));
  for (int k = first; k <= last; ++k) {
    const double s = k * step_m;
    // The point on the floor plane at axial coordinate sign*s and across coordinate a.
    auto at = [&](double a) {
      Eigen::Vector3d p = axis * (sign * s) + side * a;
      p -= (n.dot(p) + floor->offset_m) * n;  // onto the plane along its normal
      return Eigen::Vector3d(p + n * kLift_m);
    };
    const Eigen::Vector3d a = at(across_lo), b = at(across_hi);
    const vtkIdType ia = points->InsertNextPoint(a.x(), a.y(), a.z());
    const vtkIdType ib = points->InsertNextPoint(b.x(), b.y(), b.z());
    const vtkIdType ids[2] = {ia, ib};
    lines->InsertNextCell(2, ids);
    if (label_every > 0 && k % label_every == 0) {
      char text[32];
      std::snprintf(text, sizeof text, "%g m", s);
      labels.add(a, text);
    }
  }
  return g;
}

}  // namespace tunnelmap::scene
