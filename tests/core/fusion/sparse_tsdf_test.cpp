// The sparse TSDF: blocks only along the observed surfaces, the same surface as the dense
// volume, memory that does not depend on how the girder lies in the world, chunked meshes
// that join without seams, and incremental re-meshing of the changed chunks only.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "core/fusion/fusion_options.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/tsdf_volume.h"
#include "core/fusion/fuse_dataset.h"
#include "core/io/dataset.h"
#include "core/io/refined_dataset.h"
#include "core/kinematics/frame_pose.h"
#include "mesh/sparse_mesher.h"
#include "mesh/tsdf_mesher.h"
#include "tests/core/fusion/wall_frame.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_sim_walk.h"

using namespace tunnelmap;
using tunnelmap::testing::IoTempDir;
using tunnelmap::testing::flat_wall;

namespace {


TsdfOptions options_10mm(const FusionOptions& o) {
  TsdfOptions t = tsdf_options(o);
  t.threads = 2;
  return t;
}

// Lattice edges per vertex position, as a check for duplicates at chunk seams.
std::size_t distinct_positions(const TriangleMesh& m) {
  std::set<std::array<long, 3>> seen;
  for (const Eigen::Vector3f& v : m.vertices)
    seen.insert({std::lround(v.x() * 1e5), std::lround(v.y() * 1e5), std::lround(v.z() * 1e5)});
  return seen.size();
}

// A walk of the lab girder over 3 m (4 stops, exact poses), written once per build and shared by
// every test here: tests read it and write into their own folder.
class SparseWalk : public ::testing::Test {
 protected:
  static std::unique_ptr<Dataset> walk;

  static void SetUpTestSuite() {
    std::string error;
    walk = tunnelmap::testing::shared_sim_walk("SparseWalk", {"lab", 8, 0.0, 3.0, 4}, error);
    ASSERT_TRUE(walk) << error;
  }
  static void TearDownTestSuite() { walk.reset(); }

  static Eigen::Isometry3d pose(std::size_t i) { return *resolve_frame_pose(*walk, i).pose; }
  IoTempDir tmp;  // this test's own outputs
};
std::unique_ptr<Dataset> SparseWalk::walk;

}  // namespace

TEST(SparseTsdf, FlatWallAllocatesOnlyTheBandAndMeshesLikeTheDenseVolume) {
  const DepthFrame f = flat_wall(1.0);
  Parameters p;
  p.set("fusion.voxel_mm", 10.0);
  const FusionOptions o = fusion_options(p);
  SparseTsdfVolume sparse(o.voxel_m, options_10mm(o));
  Eigen::AlignedBox3d box;
  extend_depth_bounds(f, Eigen::Isometry3d::Identity(), o, box);
  TsdfVolume dense(fusion_grid(box, o), options_10mm(o));
  for (int k = 0; k < 3; ++k) {
    sparse.integrate(f, Eigen::Isometry3d::Identity());
    dense.integrate(f, Eigen::Isometry3d::Identity());
  }
  // The wall patch is ~1.12 x 0.84 m; blocks are 80 mm: 15 x 11 across, and the 60 mm band
  // around z = 1 m spans at most two block layers (z from 0.97 to 1.03).
  EXPECT_GE(sparse.block_count(), 14u * 10u);
  EXPECT_LE(sparse.block_count(), 16u * 12u * 2u);
  EXPECT_EQ(sparse.voxel_count(), sparse.block_count() * 512u);
  EXPECT_EQ(sparse.find(Eigen::Vector3i(0, 0, 6)), nullptr);  // free space at z = 0.5 m
  EXPECT_NE(sparse.find(Eigen::Vector3i(0, 0, 12)), nullptr);  // z = 0.96 .. 1.04 m
  EXPECT_LT(sparse.memory_bytes(), dense.memory_bytes());

  MeshStats st;
  const TriangleMesh m = extract_mesh(sparse, 2, &st);
  const TriangleMesh d = extract_mesh(dense, 2);
  ASSERT_EQ(m.normals.size(), m.vertices.size());
  ASSERT_EQ(m.colors.size(), m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    ASSERT_NEAR(m.vertices[i].z(), 1.0, 0.002);
    ASSERT_LT(m.normals[i].z(), 0.0f);
    ASSERT_NEAR(m.colors[i][0], 200, 2);
    ASSERT_NEAR(m.colors[i][2], 50, 2);
  }
  EXPECT_GT(st.dropped_unseen, 0u);  // the false sheet behind the wall
  EXPECT_NEAR(double(m.vertices.size()), double(d.vertices.size()), 0.05 * double(d.vertices.size()));
  EXPECT_EQ(distinct_positions(m), m.vertices.size());  // merged at the chunk seams
}

TEST(SparseTsdf, RefusesDataBeyondTheSafetyExtent) {
  TsdfOptions t;
  SparseVolumeLimits limits;
  limits.max_extent_m = 0.5;
  SparseTsdfVolume v(0.01, t, limits);
  DepthFrame f = flat_wall(1.0);
  EXPECT_THROW(v.integrate(f, Eigen::Isometry3d::Identity()), ParameterError);  // 1.1 m wide
  EXPECT_THROW(SparseTsdfVolume(0.0, t), ParameterError);
}

TEST_F(SparseWalk, MemoryIsTheSameWhenTheGirderLiesDiagonally) {
  Parameters p;
  p.set("fusion.voxel_mm", 10.0);
  const FusionOptions o = fusion_options(p);
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::vector<Eigen::Isometry3d> turned;
  for (std::size_t i = 0; i < walk->frames.size(); ++i) turned.push_back(turn * pose(i));
  write_dataset_with_poses(*walk, turned, tmp.file("diagonal"));
  FuseSettings s;
  s.refine_poses = false;  // exact poses: the two runs fuse the same frames at the same poses
  const FusionResult along = fuse_dataset(*walk, p, s);
  const FusionResult diagonal = fuse_dataset(read_dataset(tmp.file("diagonal")), p, s);
  // The lattice turned with the girder's heading (to a multiple of 90 deg from it).
  EXPECT_TRUE(along.volume->lattice_to_world().isIdentity(0.0));
  const Eigen::Vector3d lattice_x = diagonal.volume->lattice_to_world().col(0);
  const Eigen::Vector3d heading = turn.linear().col(0);
  EXPECT_GT(std::max(std::abs(lattice_x.dot(heading)), lattice_x.cross(heading).norm()), 0.999);
  const double ratio = double(diagonal.volume->memory_bytes()) / double(along.volume->memory_bytes());

  // For comparison: the dense box.
  Eigen::AlignedBox3d box_along, box_diagonal;
  for (std::size_t i = 0; i < walk->frames.size(); ++i) {
    const DepthFrame f = walk->load_frame(i);
    extend_depth_bounds(f, pose(i), o, box_along);
    extend_depth_bounds(f, turned[i], o, box_diagonal);
  }
  const double dense_ratio = double(fusion_grid(box_diagonal, o).count()) / double(fusion_grid(box_along, o).count());
  std::printf("walk of %zu frames: %zu / %zu blocks (ratio %.3f); dense box ratio %.2f\n",
              walk->frames.size(), along.volume->block_count(), diagonal.volume->block_count(), ratio,
              dense_ratio);
  EXPECT_NEAR(ratio, 1.0, 0.10);
  EXPECT_GT(dense_ratio, 1.5);  // what the bounding box would have cost
}

TEST_F(SparseWalk, IncrementalMeshingRedoesOnlyTheChangedChunks) {
  Parameters p;
  p.set("fusion.voxel_mm", 10.0);
  const FusionOptions o = fusion_options(p);
  SparseTsdfVolume v(o.voxel_m, options_10mm(o));
  IncrementalMesher mesher(o.min_weight);
  const std::size_t n = walk->frames.size();
  for (std::size_t i = 0; i + 2 < n; ++i) v.integrate(walk->load_frame(i), pose(i));
  const std::size_t first = mesher.update(v);
  EXPECT_EQ(first, chunks_affected_by(v.blocks_touched_since(0)).size());
  // The last stop (two frames) sees the girder's far end: only the chunks there change.
  for (std::size_t i = n - 2; i < n; ++i) v.integrate(walk->load_frame(i), pose(i));
  const std::size_t second = mesher.update(v);
  const std::size_t all = occupied_chunks(v).size();
  std::printf("incremental: %zu chunks, then %zu of %zu\n", first, second, all);
  EXPECT_GT(second, 0u);
  EXPECT_LT(second, all);
  // The kept and the re-extracted chunks together are the mesh extracted from scratch.
  const TriangleMesh inc = mesher.mesh(), full = extract_mesh(v, o.min_weight);
  ASSERT_EQ(inc.vertices.size(), full.vertices.size());
  ASSERT_EQ(inc.triangles.size(), full.triangles.size());
  // The same surface: the chunks are joined in the same order, so vertex for vertex.
  for (std::size_t i = 0; i < full.vertices.size(); ++i) ASSERT_EQ(inc.vertices[i], full.vertices[i]) << i;
  EXPECT_EQ(inc.triangles, full.triangles);
  EXPECT_EQ(mesher.update(v), 0u);  // nothing new
}

TEST_F(SparseWalk, ReleasingExtractionGivesTheSameMeshAndFreesTheVolume) {
  Parameters p;
  p.set("fusion.voxel_mm", 10.0);
  const FusionOptions o = fusion_options(p);
  SparseTsdfVolume v(o.voxel_m, options_10mm(o));
  for (std::size_t i = 0; i < walk->frames.size(); ++i) v.integrate(walk->load_frame(i), pose(i));
  const TriangleMesh full = extract_mesh(v, o.min_weight);
  const std::size_t blocks = v.block_count();
  const TriangleMesh swept = extract_mesh_releasing(v, o.min_weight);
  std::printf("releasing extraction: %zu vertices, %zu triangles from %zu blocks\n", swept.vertices.size(),
              swept.triangles.size(), blocks);
  EXPECT_EQ(v.block_count(), 0u);
  EXPECT_EQ(v.find(Eigen::Vector3i::Zero()), nullptr);
  // The walk runs along x: the sweep visits the chunks in the same order, so the same mesh.
  ASSERT_EQ(swept.vertices.size(), full.vertices.size());
  ASSERT_EQ(swept.triangles.size(), full.triangles.size());
  for (std::size_t i = 0; i < full.vertices.size(); ++i) ASSERT_EQ(swept.vertices[i], full.vertices[i]) << i;
  EXPECT_EQ(swept.triangles, full.triangles);
}

TEST(SparseTsdf, ReleasedBlocksAreGoneAndTheOthersStayFindable) {
  FusionOptions o;
  SparseTsdfVolume v(0.01, tsdf_options(o));
  v.integrate(flat_wall(1.0), Eigen::Isometry3d::Identity());
  const std::size_t before = v.block_count();
  std::size_t below = 0;
  for (const auto& b : v.blocks()) below += b->coords.x() < 0;
  ASSERT_GT(below, 0u);
  ASSERT_LT(below, before);
  EXPECT_EQ(v.release_blocks_below(0, 0), below);
  EXPECT_EQ(v.block_count(), before - below);
  for (const auto& b : v.blocks()) {
    EXPECT_GE(b->coords.x(), 0);
    EXPECT_EQ(v.find(b->coords), b.get());
  }
  EXPECT_EQ(v.find(Eigen::Vector3i(-1, 0, 12)), nullptr);
}

