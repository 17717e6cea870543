#include "ui/scene/measurement.h"

#include "ui/scene/label_points.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkPoints.h>
#include <vtkProp.h>

#include <cmath>
#include <cstdio>

namespace tunnelmap::scene {

std::optional<Eigen::Vector3d> pick_point(vtkRenderer* renderer, double x, double y) {
  // The depth buffer of the last render: exactly the surface the user sees under the cursor
  // (a nearest-point-to-ray picker drifts by centimetres along walls seen at a grazing angle).
  // The nearest drawn pixel within 3 px counts, so a click between sparse points still lands.
  const int* size = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
  if (!size) return std::nullopt;
  double best_z = 1.0, bx = x, by = y;
  int best_r2 = 1 << 30;
  for (int dy = -3; dy <= 3; ++dy)
    for (int dx = -3; dx <= 3; ++dx) {
      const int px = static_cast<int>(std::lround(x)) + dx, py = static_cast<int>(std::lround(y)) + dy;
      if (px < 0 || py < 0 || px >= size[0] || py >= size[1]) continue;
      const double z = renderer->GetZ(px, py);
      const int r2 = dx * dx + dy * dy;
      if (z < 1.0 && r2 < best_r2) best_r2 = r2, best_z = z, bx = px, by = py;
    }
  if (best_z >= 1.0) return std::nullopt;  // background all around
  renderer->SetDisplayPoint(bx, by, best_z);
  renderer->DisplayToWorld();
  const double* w = renderer->GetWorldPoint();
  if (w[3] == 0.0) return std::nullopt;
  return Eigen::Vector3d(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
}

void Measurement::add(const Eigen::Vector3d& p) {
  if (picks.size() >= 2) picks.clear();
  picks.push_back(p);
}

std::optional<double> Measurement::distance_m() const {
  if (picks.size() < 2) return std::nullopt;
  return (picks[1] - picks[0]).norm();
}

std::string Measurement::label() const {
  const auto d = distance_m();
  if (!d) return {};
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f mm", *d * 1000.0);
  return buf;
}

void add_pick(std::vector<Measurement>& measurements, const Eigen::Vector3d& p) {
  if (measurements.empty() || measurements.back().picks.size() >= 2) measurements.emplace_back();
  measurements.back().add(p);
}

vtkSmartPointer<vtkPolyData> measurement_polydata(const std::vector<Measurement>& measurements) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const Measurement& m : measurements) {
    vtkIdType ids[2] = {0, 0};
    for (std::size_t k = 0; k < m.picks.size() && k < 2; ++k) {
      const Eigen::Vector3d& p = m.picks[k];
      ids[k] = points->InsertNextPoint(p.x(), p.y(), p.z());
      verts->InsertNextCell(1, &ids[k]);
    }
    if (m.picks.size() == 2) lines->InsertNextCell(2, ids);
  }
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->SetLines(lines);
  return poly;
}

vtkSmartPointer<vtkPolyData> measurement_label(const std::vector<Measurement>& measurements) {
  LabelPoints labels;
  for (const Measurement& m : measurements)
    if (m.distance_m()) labels.add(0.5 * (m.picks[0] + m.picks[1]), m.label());
  return labels.polydata();
}

}  // namespace tunnelmap::scene
