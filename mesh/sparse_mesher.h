#pragma once
// The chunks of a SparseTsdfVolume's mesh (extract_mesh in mesh/tsdf_mesher.h), one by one
// (4 x 4 x 4 blocks) with the same VTK flying edges and `min_weight` rule as the dense volume.
// Each chunk's image carries one voxel of its neighbours' on the low side and two on the high
// side, so every cell of the lattice belongs to exactly one chunk and the gradient normals are
// central differences everywhere; vertices on the edges two chunks share are merged by their
// lattice edge, so the pieces join without cracks or duplicate vertices.
#include <Eigen/Core>
#include <map>
#include <vector>

#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/triangle_mesh.h"
#include "mesh/tsdf_mesher.h"

namespace tunnelmap {

inline constexpr int kChunkBlocks = 4;

// A lattice edge: its lower voxel and the axis (0, 1, 2) it runs along.
struct LatticeEdge {
  Eigen::Vector3i voxel = Eigen::Vector3i::Zero();
  int axis = 0;
  // The vertex sits on the voxel itself, within a thousandth of a voxel (a TSDF of 0 there):
  // flying edges may then emit it once per edge meeting there, all keyed alike. Not part of
  // the key.
  bool on_voxel = false;
  bool operator==(const LatticeEdge& o) const { return axis == o.axis && voxel == o.voxel; }
};

// One chunk's part of the mesh: its vertices (with the lattice edge each lies on) and the
// triangles of the cells it owns.
struct MeshChunk {
  TriangleMesh mesh;
  std::vector<LatticeEdge> vertex_edges;  // one per vertex
  std::size_t raw_triangles = 0, dropped_unseen = 0;
};

struct ChunkLess {
  bool operator()(const Eigen::Vector3i& a, const Eigen::Vector3i& b) const {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  }
};
using ChunkMap = std::map<Eigen::Vector3i, MeshChunk, ChunkLess>;

// Chunks holding at least one allocated block, in lexicographic order.
std::vector<Eigen::Vector3i> occupied_chunks(const SparseTsdfVolume& volume);
// Chunks whose mesh depends on a voxel of these blocks (their own chunk and the neighbours
// whose border samples reach into them).
std::vector<Eigen::Vector3i> chunks_affected_by(const std::vector<Eigen::Vector3i>& blocks);

MeshChunk extract_chunk(const SparseTsdfVolume& volume, const Eigen::Vector3i& chunk, int min_weight);
// The chunks' meshes as one, vertices shared between chunks merged by lattice edge (pass the
// chunks with std::move where they are not needed after: each is freed once merged).
TriangleMesh merge_chunks(ChunkMap chunks);

// Keeps each chunk's mesh between updates: after more frames, only the chunks that their
// blocks affect are extracted again.
class IncrementalMesher {
 public:
  explicit IncrementalMesher(int min_weight) : min_weight_(min_weight) {}
  // Re-extracts the chunks the frames integrated since the last update touched; returns how
  // many chunks that was.
  std::size_t update(const SparseTsdfVolume& volume);
  TriangleMesh mesh() const { return merge_chunks(chunks_); }
  std::size_t chunk_count() const { return chunks_.size(); }

 private:
  int min_weight_;
  int frames_meshed_ = 0;
  ChunkMap chunks_;
};

}  // namespace tunnelmap
