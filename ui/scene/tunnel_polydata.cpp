#include "ui/scene/tunnel_polydata.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

namespace tunnelmap::scene {

namespace {
constexpr double kBoundaryLift_m = 0.020;  // boundary above zones above wall points
constexpr double kZoneLift_m = 0.015;

bool finite(const Eigen::Vector3d& p) { return p.allFinite(); }

// Appends a 4-corner rectangle as a closed polyline (lines) or a quad (polys).
void add_rect(const std::array<Eigen::Vector3d, 4>& corners, const Eigen::Vector3d& lift,
              vtkPoints* points, vtkCellArray* cells, bool closed_line) {
  for (const auto& c : corners)
    if (!finite(c)) return;
  const vtkIdType base = points->GetNumberOfPoints();
  for (const auto& c : corners) {
    const Eigen::Vector3d p = c + lift;
    points->InsertNextPoint(p.x(), p.y(), p.z());
  }
  cells->InsertNextCell(closed_line ? 5 : 4);
  for (int k = 0; k < 4; ++k) cells->InsertCellPoint(base + k);
  if (closed_line) cells->InsertCellPoint(base);
}

Eigen::Vector3d lift_of(const Wall& w, double amount) {
  return w.normal.allFinite() ? Eigen::Vector3d(w.normal * amount) : Eigen::Vector3d::Zero();
}
}  // namespace

vtkSmartPointer<vtkPolyData> make_boundary_polydata(const TunnelMap& map) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  if (map.detected)
    for (const Wall& w : map.walls)
      if (w.found) add_rect(w.boundary, lift_of(w, kBoundaryLift_m), points, lines, true);
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

vtkSmartPointer<vtkPolyData> make_zones_polydata(const TunnelMap& map, ZoneKind kind) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  if (map.detected)
    for (const Wall& w : map.walls) {
      if (!w.found) continue;
      for (const ZoneRect& z : w.zones)
        if (z.kind == kind) add_rect(z.corners, lift_of(w, kZoneLift_m), points, polys, false);
    }
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

}  // namespace tunnelmap::scene
