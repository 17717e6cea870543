// The lattice's offset: fitted from the depth data, so that the same girder moved sideways and
// up by part of a block, or turned 45 deg about a point off the world's origin, allocates the
// same blocks (within 10 %) and meshes as well; and the small pieces the fit is built from.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/lattice_offset.h"
#include "core/fusion/mesh_accuracy.h"
#include "core/io/dataset.h"
#include "core/io/refined_dataset.h"
#include "core/kinematics/frame_pose.h"
#include "mesh/sparse_mesher.h"
#include "tests/core/fusion/wall_frame.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_sim_walk.h"

using namespace tunnelmap;
using tunnelmap::testing::IoTempDir;

namespace {

// A walk of the field girder over 3 m (4 stops, exact poses), written once per build.
class OffsetWalk : public ::testing::Test {
 protected:
  static std::unique_ptr<Dataset> walk;

  static void SetUpTestSuite() {
    std::string error;
    walk = tunnelmap::testing::shared_sim_walk("OffsetWalk", {"field", 8, 0.5, 3.5, 4}, error);
    ASSERT_TRUE(walk) << error;
  }
  static void TearDownTestSuite() { walk.reset(); }

  struct Fused {
    std::size_t blocks = 0;
    double within_10mm = 0.0;  // of the mesh's vertices, against the moved girder's true planes
  };

  // The walk with the whole world (poses and so surfaces) moved by `motion`, fused at exact poses.
  Fused fuse_moved(const Eigen::Isometry3d& motion, const std::string& name) {
    std::vector<Eigen::Isometry3d> moved;
    for (std::size_t i = 0; i < walk->frames.size(); ++i) moved.push_back(motion * *resolve_frame_pose(*walk, i).pose);
    write_dataset_with_poses(*walk, moved, tmp.file(name));
    FuseSettings s;
    s.refine_poses = false;  // every run fuses the same frames at the same (moved) poses
    s.threads = 2;
    FusionResult r = fuse_dataset(read_dataset(tmp.file(name)), Parameters(), s);
    Fused f;
    f.blocks = r.volume->block_count();
    const TriangleMesh mesh = extract_mesh(*r.volume, 2);
    f.within_10mm = mesh_accuracy(mesh, ground_truth_planes(walk->ground_truth), 0.010, motion.inverse()).fraction_within;
    const Eigen::Vector3d o = r.lattice.offset_m * 1000.0;
    std::printf("%-22s %6zu blocks, offset (%.0f, %.0f, %.0f) mm fitted in %.0f ms, %.2f %% within 10 mm\n",
                name.c_str(), f.blocks, o.x(), o.y(), o.z(), r.lattice.offset_fit_ms, 100.0 * f.within_10mm);
    return f;
  }

  IoTempDir tmp;
};
std::unique_ptr<Dataset> OffsetWalk::walk;

Eigen::Isometry3d shifted_sideways_and_up(double mm) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.translation() = Eigen::Vector3d(0.0, mm, mm) / 1000.0;
  return m;
}

// Turned by `deg` about the vertical through (x, y).
Eigen::Isometry3d turned_about(double deg, double x, double y) {
  const Eigen::Vector3d pivot(x, y, 0.0);
  return Eigen::Translation3d(pivot) * Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
         Eigen::Translation3d(-pivot);
}

}  // namespace

TEST_F(OffsetWalk, MemoryDoesNotDependOnWhereTheWorldsOriginIs) {
  std::vector<Fused> runs;
  for (const double mm : {0.0, 24.0, 32.0, 40.0})
    runs.push_back(fuse_moved(shifted_sideways_and_up(mm), "moved_" + std::to_string(int(mm)) + "mm"));
  runs.push_back(fuse_moved(turned_about(45.0, 1.37, -0.41), "turned_45_off_origin"));
  const auto [fewest, most] = std::minmax_element(runs.begin(), runs.end(),
                                                  [](const Fused& a, const Fused& b) { return a.blocks < b.blocks; });
  EXPECT_LE(double(most->blocks), 1.10 * double(fewest->blocks));
  for (const Fused& f : runs) EXPECT_NEAR(f.within_10mm, runs.front().within_10mm, 0.01);
  EXPECT_GT(runs.front().within_10mm, 0.95);
}

TEST(LatticeOffset, SpreadsTheSampleEvenlyOverTheWalk) {
  EXPECT_EQ(evenly_spread(100, 4), (std::vector<std::size_t>{12, 37, 62, 87}));
  EXPECT_EQ(evenly_spread(3, 16), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_TRUE(evenly_spread(0, 16).empty());
  EXPECT_TRUE(evenly_spread(10, 0).empty());
}

TEST(LatticeOffset, SubsampledFrameKeepsEachPixelsRay) {
  DepthFrame f = tunnelmap::testing::flat_wall(1.0);
  f.depth[static_cast<std::size_t>(32 * f.width + 12)] = 1234.0f;
  const DepthFrame s = every_nth_row(f, 16);
  EXPECT_EQ(s.width, 160);
  EXPECT_EQ(s.height, 8);
  EXPECT_EQ(s.depth.size(), std::size_t(160 * 8));
  EXPECT_EQ(s.depth.at(static_cast<std::size_t>(2 * s.width + 12)), 1234.0f);
  EXPECT_TRUE(s.intrinsics.ray(12, 2).isApprox(f.intrinsics.ray(12, 32)));
}

TEST(LatticeOffset, PutsAWallsBandInOneLayerOfBlocks) {
  // A wall 1.0 m ahead: its 60 mm band [0.97, 1.03] spans two 64 mm block layers at the
  // world's origin (the boundary at 1.024 m) and one when the lattice moves it inside a layer.
  std::vector<PosedDepth> sample{{tunnelmap::testing::flat_wall(1.0), Eigen::Isometry3d::Identity()}};
  const LatticeOffsetFit fit = fit_lattice_offset(sample, Eigen::Matrix3d::Identity(), 0.008, TsdfOptions());
  EXPECT_LT(double(fit.blocks_fitted), 0.6 * double(fit.blocks_at_zero));
  const double block_m = 0.064;
  const double band_start = std::fmod(0.97 - fit.offset_m.z(), block_m);  // within its layer
  EXPECT_LE(band_start + 0.06, block_m + 1e-9);
  EXPECT_TRUE((fit.offset_m.array() >= 0.0).all() && (fit.offset_m.array() < block_m).all());
}
