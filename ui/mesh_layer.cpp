#include "ui/mesh_layer.h"

#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include "ui/mesh_level_of_detail.h"
#include "ui/scene/mesh_polydata.h"

namespace tunnelmap::ui {

vtkSmartPointer<vtkPolyData> ply_mesh_polydata(const PlyMesh& m, const PieceProgress& progress) {
  auto poly = scene::mesh_polydata(m);
  if (m.normals.size() == m.vertices.size() && !m.normals.empty()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(m.normals.size()));
    for (std::size_t i = 0; i < m.normals.size(); ++i)
      for (int k = 0; k < 3; ++k) normals->SetTypedComponent(static_cast<vtkIdType>(i), k, m.normals[i][k]);
    poly->GetPointData()->SetNormals(normals);
  }
  return with_level_of_detail(poly, progress);
}

vtkSmartPointer<vtkPolyData> mesh_in_camera_frame(vtkPolyData* world_mesh, const Eigen::Isometry3d& world_to_camera) {
  if (const MeshLevelOfDetail* lod = level_of_detail(world_mesh))
    return near_full_far_coarse(*lod, world_to_camera);
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->ShallowCopy(world_mesh);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(world_mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < world_mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    world_mesh->GetPoint(i, p);
    const Eigen::Vector3d q = world_to_camera * Eigen::Vector3d(p[0], p[1], p[2]);
    points->SetPoint(i, q.data());
  }
  moved->SetPoints(points);
  moved->GetPointData()->SetNormals(nullptr);
  return moved;
}

}  // namespace tunnelmap::ui
