#include "mesh/tsdf_mesher.h"

#include <vtkCellArray.h>

#include <chrono>

#include "mesh/flying_edges.h"

namespace tunnelmap {

TriangleMesh extract_mesh(const TsdfVolume& volume, int min_weight, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const VoxelGrid& g = volume.grid();
  const vtkSmartPointer<vtkImageData> image =
      wrap_tsdf_image(g.dims, g.origin, g.voxel_m, volume.tsdf().data(), volume.rgb().data());
  const vtkSmartPointer<vtkPolyData> poly = zero_level_set(image);

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
    const Eigen::Vector3i c = triangle_cell(poly, ids, g.origin, g.voxel_m);
    bool ok = true;
    for (int k = 0; k < 8 && ok; ++k) ok = seen(c.x() + (k & 1), c.y() + ((k >> 1) & 1), c.z() + ((k >> 2) & 1));
    if (!ok) {
      ++st.dropped_unseen;
      continue;
    }
    std::array<std::int32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      std::int32_t& m = remap[static_cast<std::size_t>(ids[k])];
      if (m < 0) {
        m = static_cast<std::int32_t>(mesh.vertices.size());
        append_contour_vertex(poly, ids[k], Eigen::Vector3d::Zero(), 1.0, mesh);
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
