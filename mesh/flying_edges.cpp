#include "mesh/flying_edges.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace tunnelmap {

vtkSmartPointer<vtkImageData> wrap_tsdf_image(const Eigen::Vector3i& dims, const Eigen::Vector3d& origin,
                                              double spacing, const float* tsdf, const std::uint8_t* rgb) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims.x(), dims.y(), dims.z());
  image->SetOrigin(origin.x(), origin.y(), origin.z());
  image->SetSpacing(spacing, spacing, spacing);
  const vtkIdType count = vtkIdType(dims.x()) * dims.y() * dims.z();
  // save = 1: VTK neither copies nor frees the buffers (read only).
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("tsdf");
  scalars->SetArray(const_cast<float*>(tsdf), count, 1);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("rgb");
  colours->SetNumberOfComponents(3);
  colours->SetArray(const_cast<std::uint8_t*>(rgb), count * 3, 1);
  image->GetPointData()->SetScalars(scalars);
  image->GetPointData()->AddArray(colours);
  return image;
}

vtkSmartPointer<vtkPolyData> zero_level_set(vtkImageData* image) {
  vtkNew<vtkFlyingEdges3D> fe;
  fe->SetInputData(image);
  fe->SetValue(0, 0.0);
  fe->ComputeNormalsOn();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  fe->InterpolateAttributesOn();
  fe->Update();
  vtkSmartPointer<vtkPolyData> out = fe->GetOutput();
  return out;
}

void append_contour_vertex(vtkPolyData* poly, vtkIdType id, const Eigen::Vector3d& offset, double scale,
                           TriangleMesh& mesh) {
  double p[3];
  poly->GetPoint(id, p);
  const Eigen::Vector3d w = offset + scale * Eigen::Vector3d(p[0], p[1], p[2]);
  mesh.vertices.emplace_back(w.cast<float>());
  if (vtkDataArray* normals = poly->GetPointData()->GetNormals()) {
    double n[3];
    normals->GetTuple(id, n);
    // VTK's contour normals follow the negative gradient; the TSDF grows into free space.
    mesh.normals.emplace_back(Eigen::Vector3f(float(-n[0]), float(-n[1]), float(-n[2])).normalized());
  }
  if (vtkDataArray* colours = poly->GetPointData()->GetArray("rgb")) {
    double c[3];
    colours->GetTuple(id, c);
    mesh.colors.push_back({static_cast<std::uint8_t>(std::lround(c[0])),
                           static_cast<std::uint8_t>(std::lround(c[1])),
                           static_cast<std::uint8_t>(std::lround(c[2]))});
  }
}

namespace {
// The corner (lowest sample) of the cell holding the triangle (its centroid's cell).
Eigen::Vector3i triangle_cell(vtkPolyData* poly, const vtkIdType* ids) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    double p[3];
    poly->GetPoint(ids[k], p);
    c += Eigen::Vector3d(p[0], p[1], p[2]) / 3.0;
  }
  return {int(std::floor(c.x())), int(std::floor(c.y())), int(std::floor(c.z()))};
}
}  // namespace

void copy_kept_triangles(vtkPolyData* poly, const std::function<CellVerdict(const Eigen::Vector3i&)>& verdict,
                         const Eigen::Vector3d& offset, double scale, TriangleMesh& mesh, MeshStats& stats,
                         const std::function<void(vtkIdType)>& on_new_vertex) {
  std::vector<std::int32_t> remap(static_cast<std::size_t>(poly->GetNumberOfPoints()), -1);
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  while (polys->GetNextCell(npts, ids)) {
    if (npts != 3) continue;
    const CellVerdict v = verdict(triangle_cell(poly, ids));
    if (v == CellVerdict::Foreign) continue;
    ++stats.raw_triangles;
    if (v == CellVerdict::Unseen) {
      ++stats.dropped_unseen;
      continue;
    }
    std::array<std::int32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      std::int32_t& m = remap[static_cast<std::size_t>(ids[k])];
      if (m < 0) {
        m = static_cast<std::int32_t>(mesh.vertices.size());
        append_contour_vertex(poly, ids[k], offset, scale, mesh);
        if (on_new_vertex) on_new_vertex(ids[k]);
      }
      tri[k] = m;
    }
    mesh.triangles.push_back(tri);
  }
}

}  // namespace tunnelmap
