#include "mesh/tsdf_mesher.h"

#include <chrono>

#include "mesh/flying_edges.h"

namespace tunnelmap {

TriangleMesh extract_mesh(const TsdfVolume& volume, int min_weight, MeshStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  const VoxelGrid& g = volume.grid();
  // Spacing 1 from the origin 0: sample units, so that cells are integer corners.
  const vtkSmartPointer<vtkImageData> image =
      wrap_tsdf_image(g.dims, Eigen::Vector3d::Zero(), 1.0, volume.tsdf().data(), volume.rgb().data());
  const vtkSmartPointer<vtkPolyData> poly = zero_level_set(image);

  const std::vector<std::uint16_t>& w = volume.weight();
  auto seen = [&](int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < g.dims.x() && y < g.dims.y() && z < g.dims.z() &&
           w[g.index(x, y, z)] >= min_weight;
  };
  auto verdict = [&](const Eigen::Vector3i& c) {
    for (int k = 0; k < 8; ++k)
      if (!seen(c.x() + (k & 1), c.y() + ((k >> 1) & 1), c.z() + ((k >> 2) & 1))) return CellVerdict::Unseen;
    return CellVerdict::Kept;
  };
  TriangleMesh mesh;
  MeshStats st;
  copy_kept_triangles(poly, verdict, g.origin, g.voxel_m, mesh, st);
  st.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  return mesh;
}

}  // namespace tunnelmap
