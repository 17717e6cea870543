#include "ui/scene/frustum_polydata.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>

namespace tunnelmap::scene {

vtkSmartPointer<vtkPolyData> make_frustum_polydata(const Intrinsics& k, double depth_m) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  points->InsertNextPoint(0, 0, 0);
  const double us[] = {0.0, k.width - 1.0, k.width - 1.0, 0.0};
  const double vs[] = {0.0, 0.0, k.height - 1.0, k.height - 1.0};
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r = k.ray(us[i], vs[i]) * depth_m;
    points->InsertNextPoint(r.x(), r.y(), r.z());
  }
  for (vtkIdType i = 1; i <= 4; ++i) {
    const vtkIdType apex_edge[] = {0, i};
    lines->InsertNextCell(2, apex_edge);
    const vtkIdType rim_edge[] = {i, i % 4 + 1};
    lines->InsertNextCell(2, rim_edge);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

}  // namespace tunnelmap::scene
