#pragma once
// A triangle mesh (TriangleMesh from fusion, PlyMesh from a file: both have vertices, colors
// and triangles) as VTK polydata, colours as the "RGB" point scalars.
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <cstddef>

namespace tunnelmap::scene {

// The triangles for which `keep(face index)` is true; every vertex is kept (unused ones draw
// nothing).
template <typename Mesh, typename Keep>
vtkSmartPointer<vtkPolyData> mesh_polydata(const Mesh& mesh, Keep keep) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].x(), mesh.vertices[i].y(),
                     mesh.vertices[i].z());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!keep(f)) continue;
    const auto& t = mesh.triangles[f];
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (mesh.colors.size() == mesh.vertices.size()) {
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetName("RGB");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(static_cast<vtkIdType>(mesh.colors.size()));
    for (std::size_t i = 0; i < mesh.colors.size(); ++i)
      for (int c = 0; c < 3; ++c) colors->SetTypedComponent(static_cast<vtkIdType>(i), c, mesh.colors[i][c]);
    poly->GetPointData()->SetScalars(colors);
  }
  return poly;
}

template <typename Mesh>
vtkSmartPointer<vtkPolyData> mesh_polydata(const Mesh& mesh) {
  return mesh_polydata(mesh, [](std::size_t) { return true; });
}

}  // namespace tunnelmap::scene
