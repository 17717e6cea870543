#include "mesh/tsdf_mesher.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <chrono>
#include <cmath>

namespace tunnelmap {

TriangleMesh extract_mesh(const TsdfVolume& volume, int min_weight, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const VoxelGrid& g = volume.grid();
  vtkNew<vtkImageData> image;
  image->SetDimensions(g.dims.x(), g.dims.y(), g.dims.z());
  image->SetOrigin(g.origin.x(), g.origin.y(), g.origin.z());
  image->SetSpacing(g.voxel_m, g.voxel_m, g.voxel_m);
  // Wrap the volume's buffers (save = 1: VTK neither copies nor frees them; read only).
  vtkNew<vtkFloatArray> tsdf;
  tsdf->SetName("tsdf");
  tsdf->SetArray(const_cast<float*>(volume.tsdf().data()), static_cast<vtkIdType>(g.count()), 1);
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetName("rgb");
  rgb->SetNumberOfComponents(3);
  rgb->SetArray(const_cast<std::uint8_t*>(volume.rgb().data()),
                static_cast<vtkIdType>(g.count() * 3), 1);
  image->GetPointData()->SetScalars(tsdf);
  image->GetPointData()->AddArray(rgb);

  vtkNew<vtkFlyingEdges3D> fe;
  fe->SetInputData(image);
  fe->SetValue(0, 0.0);
  fe->ComputeNormalsOn();
  fe->ComputeGradientsOff();
  fe->ComputeScalarsOff();
  fe->InterpolateAttributesOn();
  fe->Update();
  vtkPolyData* poly = fe->GetOutput();

  vtkDataArray* normals = poly->GetPointData()->GetNormals();
  vtkDataArray* colours = poly->GetPointData()->GetArray("rgb");
  const std::vector<std::uint16_t>& w = volume.weight();
  auto seen = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < g.dims.x() && y < g.dims.y() && z < g.dims.z() &&
           w[g.index(x, y, z)] >= min_weight;
  };

  TriangleMesh mesh;
  std::vector<std::int32_t> remap(static_cast<std::size_t>(poly->GetNumberOfPoints()), -1);
  MeshStats st;
  vtkCellArray* polys = poly->GetPolys();
  polys->InitTraversal();
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  while (polys->GetNextCell(npts, ids)) {
    if (npts != 3) continue;
    ++st.raw_triangles;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      double p[3];
      poly->GetPoint(ids[k], p);
      c += Eigen::Vector3d(p[0], p[1], p[2]) / 3.0;
    }
    const Eigen::Vector3d cell = (c - g.origin) / g.voxel_m;
    const int x = int(std::floor(cell.x())), y = int(std::floor(cell.y())), z = int(std::floor(cell.z()));
    bool ok = true;
    for (int k = 0; k < 8 && ok; ++k) ok = seen(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1));
    if (!ok) {
      ++st.dropped_unseen;
      continue;
    }
    std::array<std::int32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      std::int32_t& m = remap[static_cast<std::size_t>(ids[k])];
      if (m < 0) {
        m = static_cast<std::int32_t>(mesh.vertices.size());
        double p[3];
        poly->GetPoint(ids[k], p);
        mesh.vertices.emplace_back(float(p[0]), float(p[1]), float(p[2]));
        if (normals) {
          double n[3];
          normals->GetTuple(ids[k], n);
          // VTK's contour normals follow the negative gradient; the TSDF grows into free space.
          mesh.normals.emplace_back(Eigen::Vector3f(float(-n[0]), float(-n[1]), float(-n[2])).normalized());
        }
        if (colours) {
          double rgbv[3];
          colours->GetTuple(ids[k], rgbv);
          mesh.colors.push_back({static_cast<std::uint8_t>(std::lround(rgbv[0])),
                                 static_cast<std::uint8_t>(std::lround(rgbv[1])),
                                 static_cast<std::uint8_t>(std::lround(rgbv[2]))});
        }
      }
      tri[k] = m;
    }
    mesh.triangles.push_back(tri);
  }
  st.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  return mesh;
}

}  // namespace tunnelmap
