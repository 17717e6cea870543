#include "mesh/sparse_mesher.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <functional>
#include <limits>
#include <unordered_map>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "mesh/flying_edges.h"

namespace tunnelmap {

namespace {

constexpr int kChunkVoxels = kChunkBlocks * kBlockSide;
// Samples per side: one voxel before the chunk, its own, and two after (the last cells' far
// corners and their gradients).
constexpr int kChunkSamples = kChunkVoxels + 3;

int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// The chunk's samples, global voxel c0 - 1 + l at local index l; unallocated voxels are the
// never-seen value (+1, weight 0).
struct ChunkSamples {
  std::vector<float> tsdf = std::vector<float>(std::size_t(kChunkSamples) * kChunkSamples * kChunkSamples, 1.0f);
  std::vector<std::uint16_t> weight = std::vector<std::uint16_t>(tsdf.size(), 0);
  std::vector<std::uint8_t> rgb = std::vector<std::uint8_t>(tsdf.size() * 3, 0);

  static std::size_t index(int x, int y, int z) {
    return (std::size_t(z) * kChunkSamples + y) * kChunkSamples + x;
  }
};

void copy_block(const VoxelBlock& b, const Eigen::Vector3i& first_sample, ChunkSamples& s) {
  const Eigen::Vector3i base = b.coords * kBlockSide - first_sample;  // block voxel 0, local
  for (int z = 0; z < kBlockSide; ++z) {
    const int lz = base.z() + z;
    if (lz < 0 || lz >= kChunkSamples) continue;
    for (int y = 0; y < kBlockSide; ++y) {
      const int ly = base.y() + y;
      if (ly < 0 || ly >= kChunkSamples) continue;
      for (int x = 0; x < kBlockSide; ++x) {
        const int lx = base.x() + x;
        if (lx < 0 || lx >= kChunkSamples) continue;
        const int from = VoxelBlock::local_index(x, y, z);
        const std::size_t to = ChunkSamples::index(lx, ly, lz);
        s.tsdf[to] = b.tsdf[std::size_t(from)];
        s.weight[to] = b.weight[std::size_t(from)];
        for (int k = 0; k < 3; ++k) s.rgb[to * 3 + k] = b.rgb[std::size_t(from) * 3 + k];
      }
    }
  }
}

ChunkSamples gather_samples(const SparseTsdfVolume& volume, const Eigen::Vector3i& chunk) {
  ChunkSamples s;
  const Eigen::Vector3i first = chunk * kChunkVoxels - Eigen::Vector3i::Ones();
  const Eigen::Vector3i lo = chunk * kChunkBlocks - Eigen::Vector3i::Ones();
  const Eigen::Vector3i hi = chunk * kChunkBlocks + Eigen::Vector3i::Constant(kChunkBlocks);
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x)
        if (const VoxelBlock* b = volume.find({x, y, z})) copy_block(*b, first, s);
  return s;
}

// The lattice edge a contour vertex (local sample units) lies on: the coordinate farthest
// from a sample is the one along the edge.
LatticeEdge edge_of(const double* q, const Eigen::Vector3i& first_sample) {
  int axis = 0;
  double best = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double off = std::abs(q[k] - std::round(q[k]));
    if (off > best) best = off, axis = k;
  }
  LatticeEdge e;
  e.axis = axis;
  e.on_voxel = best < 1e-3;  // float vertices of a 35-sample image are ~4e-6 apart
  for (int k = 0; k < 3; ++k)
    e.voxel[k] = first_sample[k] + int(k == axis ? std::floor(q[k]) : std::round(q[k]));
  return e;
}

// Turns the lattice-frame vertices and normals into the world frame.
void to_world(const Eigen::Matrix3d& lattice_to_world, const Eigen::Vector3d& lattice_origin, TriangleMesh& mesh) {
  if (lattice_to_world.isIdentity(0.0) && lattice_origin.isZero(0.0)) return;
  const Eigen::Matrix3f R = lattice_to_world.cast<float>();
  const Eigen::Vector3f t = lattice_origin.cast<float>();
  for (Eigen::Vector3f& v : mesh.vertices) v = R * v + t;
  for (Eigen::Vector3f& n : mesh.normals) n = R * n;
}

struct LatticeEdgeHash {
  std::size_t operator()(const LatticeEdge& e) const {
    return BlockCoordsHash()(e.voxel) * 4u + static_cast<std::size_t>(e.axis);
  }
};

}  // namespace

std::vector<Eigen::Vector3i> occupied_chunks(const SparseTsdfVolume& volume) {
  std::set<Eigen::Vector3i, ChunkLess> chunks;
  for (const auto& b : volume.blocks())
    chunks.insert({floor_div(b->coords.x(), kChunkBlocks), floor_div(b->coords.y(), kChunkBlocks),
                   floor_div(b->coords.z(), kChunkBlocks)});
  return {chunks.begin(), chunks.end()};
}

std::vector<Eigen::Vector3i> chunks_affected_by(const std::vector<Eigen::Vector3i>& blocks) {
  std::set<Eigen::Vector3i, ChunkLess> chunks;
  for (const Eigen::Vector3i& b : blocks) {
    // Chunk c samples voxels [32c - 1, 32c + 33]; the block holds [8b, 8b + 7].
    Eigen::Vector3i lo, hi;
    for (int k = 0; k < 3; ++k) {
      lo[k] = floor_div(b[k] * kBlockSide - (kChunkVoxels + 1) + kChunkVoxels - 1, kChunkVoxels);
      hi[k] = floor_div(b[k] * kBlockSide + kBlockSide, kChunkVoxels);
    }
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y)
        for (int x = lo.x(); x <= hi.x(); ++x) chunks.insert({x, y, z});
  }
  return {chunks.begin(), chunks.end()};
}

MeshChunk extract_chunk(const SparseTsdfVolume& volume, const Eigen::Vector3i& chunk, int min_weight) {
  const ChunkSamples s = gather_samples(volume, chunk);
  const Eigen::Vector3i first = chunk * kChunkVoxels - Eigen::Vector3i::Ones();
  const vtkSmartPointer<vtkImageData> image = wrap_tsdf_image(
      Eigen::Vector3i::Constant(kChunkSamples), Eigen::Vector3d::Zero(), 1.0, s.tsdf.data(), s.rgb.data());
  const vtkSmartPointer<vtkPolyData> poly = zero_level_set(image);

  auto seen = [&](int x, int y, int z) { return s.weight[ChunkSamples::index(x, y, z)] >= min_weight; };
  auto verdict = [&](const Eigen::Vector3i& c) {
    if (c.minCoeff() < 1 || c.maxCoeff() > kChunkVoxels) return CellVerdict::Foreign;  // a neighbour's
    for (int k = 0; k < 8; ++k)
      if (!seen(c.x() + (k & 1), c.y() + ((k >> 1) & 1), c.z() + ((k >> 2) & 1))) return CellVerdict::Unseen;
    return CellVerdict::Kept;
  };
  MeshChunk out;
  MeshStats st;
  copy_kept_triangles(poly, verdict, first.cast<double>() * volume.voxel_m(), volume.voxel_m(), out.mesh, st,
                      [&](vtkIdType id) {
                        double q[3];
                        poly->GetPoint(id, q);
                        out.vertex_edges.push_back(edge_of(q, first));
                      });
  to_world(volume.lattice_to_world(), volume.lattice_origin(), out.mesh);
  out.raw_triangles = st.raw_triangles;
  out.dropped_unseen = st.dropped_unseen;
  return out;
}

namespace {

// Only a vertex on a chunk's boundary plane can belong to two chunks (a chunk owns the cells
// whose lower voxel lies in it), so only edges that touch such a plane at either end are
// looked up: a vertex on or next to a voxel is keyed by whichever edge each chunk's flying
// edges put it on, and rounding may give it the edge that ends on the plane.
bool on_chunk_seam(const LatticeEdge& e) {
  if (e.on_voxel) return true;  // also merges the copies one chunk may hold
  Eigen::Vector3i far_end = e.voxel;
  ++far_end[e.axis];
  for (int k = 0; k < 3; ++k)
    if (e.voxel[k] % kChunkVoxels == 0 || far_end[k] % kChunkVoxels == 0) return true;
  return false;
}

void reserve_for(const ChunkMap& chunks, TriangleMesh& mesh) {
  std::size_t vertices = 0, triangles = 0;
  bool normals = false, colors = false;
  for (const auto& entry : chunks) {
    vertices += entry.second.mesh.vertices.size();
    triangles += entry.second.mesh.triangles.size();
    normals = normals || !entry.second.mesh.normals.empty();
    colors = colors || !entry.second.mesh.colors.empty();
  }
  mesh.vertices.reserve(vertices);  // an upper bound: the seam vertices come twice
  if (normals) mesh.normals.reserve(vertices);
  if (colors) mesh.colors.reserve(vertices);
  mesh.triangles.reserve(triangles);
}

// Appends one chunk, sharing its seam vertices with the chunks appended before.
void append_chunk(const MeshChunk& c,
                  std::unordered_map<LatticeEdge, std::int32_t, LatticeEdgeHash>& seam_vertex,
                  std::vector<std::int32_t>& remap, TriangleMesh& mesh) {
  remap.resize(c.mesh.vertices.size());
  for (std::size_t i = 0; i < c.mesh.vertices.size(); ++i) {
    const std::int32_t next = std::int32_t(mesh.vertices.size());
    if (on_chunk_seam(c.vertex_edges[i])) {
      const auto [it, added] = seam_vertex.try_emplace(c.vertex_edges[i], next);
      remap[i] = it->second;
      if (!added) continue;
    } else {
      remap[i] = next;
    }
    mesh.vertices.push_back(c.mesh.vertices[i]);
    if (!c.mesh.normals.empty()) mesh.normals.push_back(c.mesh.normals[i]);
    if (!c.mesh.colors.empty()) mesh.colors.push_back(c.mesh.colors[i]);
  }
  for (const auto& t : c.mesh.triangles)
    mesh.triangles.push_back({remap[std::size_t(t[0])], remap[std::size_t(t[1])], remap[std::size_t(t[2])]});
}

}  // namespace

TriangleMesh merge_chunks(ChunkMap chunks) {
  TriangleMesh mesh;
  reserve_for(chunks, mesh);
  std::unordered_map<LatticeEdge, std::int32_t, LatticeEdgeHash> seam_vertex;
  std::vector<std::int32_t> remap;
  // Each chunk is freed once appended, so the chunks and the whole mesh are not held twice.
  for (auto it = chunks.begin(); it != chunks.end(); it = chunks.erase(it))
    append_chunk(it->second, seam_vertex, remap, mesh);
  return mesh;
}

namespace {
// Extracts `which` (in parallel) into `chunks`, replacing what was there; the chunks' counts.
MeshStats extract_chunks(const SparseTsdfVolume& volume, const std::vector<Eigen::Vector3i>& which,
                         int min_weight, ChunkMap& chunks) {
  std::vector<MeshChunk> done(which.size());
  tbb::parallel_for(std::size_t(0), which.size(),
                    [&](std::size_t i) { done[i] = extract_chunk(volume, which[i], min_weight); });
  MeshStats st;
  for (std::size_t i = 0; i < which.size(); ++i) {
    st.raw_triangles += done[i].raw_triangles;
    st.dropped_unseen += done[i].dropped_unseen;
    if (done[i].mesh.triangles.empty())
      chunks.erase(which[i]);
    else
      chunks[which[i]] = std::move(done[i]);
  }
  return st;
}
}  // namespace

namespace {
// Room for the mesh reserved before extraction, ~4.5 x the vertices and 5 x the triangles per
// block of a fused girder (56 and 102): a page is resident only once written, so the unused
// rest costs address space, not memory, while a vector that grows copies itself and holds
// twice its size at that moment, beside the volume (+400 MB for a 200 m girder). A mesh that
// needs more still grows as usual.
constexpr std::size_t kReservedVerticesPerBlock = 256, kReservedTrianglesPerBlock = 512;
// A releasing extraction frees the swept blocks in this many steps along the girder (each step
// compacts the block list and index once).
constexpr int kReleaseSteps = 32;

void reserve_address_space(std::size_t blocks, TriangleMesh& mesh) {
  mesh.vertices.reserve(blocks * kReservedVerticesPerBlock);
  mesh.normals.reserve(blocks * kReservedVerticesPerBlock);
  mesh.colors.reserve(blocks * kReservedVerticesPerBlock);
  mesh.triangles.reserve(blocks * kReservedTrianglesPerBlock);
}
}  // namespace

namespace {
// Extracts `which` in batches, extracted in parallel and appended in order: only one batch's
// chunk meshes exist beside the mesh, never all of a long girder's. `after_batch` gets the last
// chunk extracted so far.
TriangleMesh extract_in_batches(const SparseTsdfVolume& volume, const std::vector<Eigen::Vector3i>& which,
                                int min_weight, MeshStats* stats,
                                const std::function<void(const Eigen::Vector3i&)>& after_batch) {
  const auto start = std::chrono::steady_clock::now();
  constexpr std::size_t kBatchChunks = 256;
  TriangleMesh mesh;
  reserve_address_space(volume.block_count(), mesh);
  MeshStats st;
  std::unordered_map<LatticeEdge, std::int32_t, LatticeEdgeHash> seam_vertex;
  std::vector<std::int32_t> remap;
  std::vector<MeshChunk> batch;
  for (std::size_t first = 0; first < which.size(); first += kBatchChunks) {
    batch.assign(std::min(kBatchChunks, which.size() - first), MeshChunk());
    tbb::parallel_for(std::size_t(0), batch.size(),
                      [&](std::size_t i) { batch[i] = extract_chunk(volume, which[first + i], min_weight); });
    for (const MeshChunk& c : batch) {
      st.raw_triangles += c.raw_triangles;
      st.dropped_unseen += c.dropped_unseen;
      if (!c.mesh.triangles.empty()) append_chunk(c, seam_vertex, remap, mesh);
    }
    if (after_batch) after_batch(which[first + batch.size() - 1]);
  }
  st.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (stats) *stats = st;
  return mesh;
}

// The lattice axis along which the volume's blocks span the most (the girder's).
int longest_axis(const std::vector<Eigen::Vector3i>& chunks) {
  Eigen::AlignedBox3i box;
  for (const Eigen::Vector3i& c : chunks) box.extend(c);
  int axis = 0;
  (box.max() - box.min()).maxCoeff(&axis);
  return axis;
}

// Gives the freed pages back to the system (the blocks are 5 KiB heap allocations).
void return_free_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}
}  // namespace

TriangleMesh extract_mesh(const SparseTsdfVolume& volume, int min_weight, MeshStats* stats) {
  return extract_in_batches(volume, occupied_chunks(volume), min_weight, stats, nullptr);
}

TriangleMesh extract_mesh_releasing(SparseTsdfVolume& volume, int min_weight, MeshStats* stats) {
  std::vector<Eigen::Vector3i> which = occupied_chunks(volume);
  if (which.empty()) return {};
  // Chunks in order along the girder: once the sweep has passed a block, no chunk left reads it.
  const int axis = longest_axis(which);
  std::stable_sort(which.begin(), which.end(),
                   [axis](const Eigen::Vector3i& a, const Eigen::Vector3i& b) { return a[axis] < b[axis]; });
  const int span_blocks = (which.back()[axis] - which.front()[axis] + 1) * kChunkBlocks;
  const int step = std::max(kChunkBlocks, span_blocks / kReleaseSteps);
  int released_below = which.front()[axis] * kChunkBlocks;
  const auto release = [&](const Eigen::Vector3i& last) {
    // Chunks before `last` along the axis are meshed; chunk c reads blocks up to 4c + 4, so
    // blocks up to 4 last - 2 are needed by none of the chunks left.
    const int below = last[axis] * kChunkBlocks - 1;
    if (below - released_below < step) return;
    volume.release_blocks_below(axis, below);
    released_below = below;
    return_free_memory();
  };
  TriangleMesh mesh = extract_in_batches(volume, which, min_weight, stats, release);
  volume.release_blocks_below(axis, std::numeric_limits<int>::max());
  return_free_memory();
  return mesh;
}

std::size_t IncrementalMesher::update(const SparseTsdfVolume& volume) {
  const std::vector<Eigen::Vector3i> which =
      chunks_affected_by(volume.blocks_touched_since(frames_meshed_));
  extract_chunks(volume, which, min_weight_, chunks_);
  frames_meshed_ = volume.frames_integrated();
  return which.size();
}

}  // namespace tunnelmap
