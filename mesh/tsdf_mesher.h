#pragma once
// Coloured triangle mesh of a TsdfVolume's zero level set (VTK vtkFlyingEdges3D, which
// interpolates the voxel colours onto the vertices and gives gradient normals).
#include "core/fusion/triangle_mesh.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/tsdf_volume.h"

namespace tunnelmap {

struct MeshStats {
  std::size_t raw_triangles = 0;      // from flying edges
  std::size_t dropped_unseen = 0;     // in cells with a voxel seen < min_weight times
  double milliseconds = 0.0;
};

// Only cells whose 8 corner voxels were each seen >= `min_weight` times keep their triangles:
// the +1 of never-seen voxels next to the -1 behind a surface would otherwise make a false
// second surface one truncation distance behind every real one. Normals point to free space.
TriangleMesh extract_mesh(const TsdfVolume& volume, int min_weight, MeshStats* stats = nullptr);
// The same for the sparse volume, chunk by chunk (mesh/sparse_mesher.h): the same vertices up to
// the lattice's offset, merged where chunks meet.
TriangleMesh extract_mesh(const SparseTsdfVolume& volume, int min_weight, MeshStats* stats = nullptr);
// The same mesh (vertices in the order of a sweep along the volume's longest lattice axis),
// freeing the blocks as the sweep passes them, so that the volume and the whole mesh are never
// held together; the volume has no blocks afterwards.
TriangleMesh extract_mesh_releasing(SparseTsdfVolume& volume, int min_weight, MeshStats* stats = nullptr);

}  // namespace tunnelmap
