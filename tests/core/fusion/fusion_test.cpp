// TSDF fusion, mesh extraction, mesh accuracy on simulated multi-pose sequences (exact and
// sagging arm), the multi-scan map merge and `tunnelmap-cli fuse`.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <set>

#include "core/export/mesh_ply.h"
#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/fusion/mesh_accuracy.h"
#include "core/fusion/tsdf_volume.h"
#include "core/io/dataset.h"
#include "core/mapping/multi_scan_map.h"
#include "core/sim/sim_dataset_writer.h"
#include "core/util/error.h"
#include "core/io/ply_mesh_reader.h"
#include "mesh/tsdf_mesher.h"
#include "tests/support/cli_runner.h"
#include "tests/core/fusion/wall_frame.h"
#include "tests/support/io_temp_dir.h"
#include "tests/support/shared_fixture.h"

using namespace tunnelmap;
using tunnelmap::testing::IoTempDir;
using tunnelmap::testing::flat_wall;

namespace {


Parameters test_params() {
  Parameters p;
  p.set("fusion.voxel_mm", 10.0);  // coarser than the default: keeps the test fast
  return p;
}

// Six VGA frames in three arm poses of the lab tunnel, without and with sag, written once per
// build and shared by every test here (they only read them).
class SimSequence : public ::testing::Test {
 protected:
  static tunnelmap::testing::SharedFixture shared;
  static std::string exact, sag;

  static void SetUpTestSuite() {
    const std::string what = "lab, 6 frames, inchworm7, sag 0 and 1 deg/m\n" + tunnelmap::testing::test_binary_stamp();
    shared = tunnelmap::testing::shared_fixture("SimSequence", what, [](const std::filesystem::path& dir) {
      SimConfig c = SimConfig::from_preset("lab");
      c.frames = 6;
      c.arm_preset = "inchworm7";
      write_sim_dataset((dir / "exact").string(), c);
      c.arm_sag_deg_per_m = 1.0;
      write_sim_dataset((dir / "sag").string(), c);
      return std::string();
    });
    ASSERT_TRUE(shared.ok()) << shared.error;
    exact = shared.file("exact");
    sag = shared.file("sag");
  }
};
tunnelmap::testing::SharedFixture SimSequence::shared;
std::string SimSequence::exact, SimSequence::sag;

}  // namespace

TEST(Fusion, FlatWallMeshIsOnThePlaneFacingTheCameraWithItsColour) {
  const DepthFrame f = flat_wall(1.0);
  FusionOptions o = fusion_options(test_params());
  Eigen::AlignedBox3d box;
  extend_depth_bounds(f, Eigen::Isometry3d::Identity(), o, box);
  TsdfVolume vol(fusion_grid(box, o), tsdf_options(o));
  for (int k = 0; k < 3; ++k) vol.integrate(f, Eigen::Isometry3d::Identity());
  EXPECT_EQ(vol.frames_integrated(), 3);
  MeshStats st;
  const TriangleMesh m = extract_mesh(vol, 2, &st);
  ASSERT_GT(m.vertices.size(), 500u);
  ASSERT_EQ(m.normals.size(), m.vertices.size());
  ASSERT_EQ(m.colors.size(), m.vertices.size());
  std::size_t facing = 0;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    ASSERT_NEAR(m.vertices[i].z(), 1.0, 0.002);      // no false surface behind the wall
    ASSERT_LT(m.normals[i].z(), 0.0f);               // towards the camera (free space)
    facing += m.normals[i].z() < -0.99f;             // tilted only at the patch's rim
    ASSERT_NEAR(m.colors[i][0], 200, 2);
    ASSERT_NEAR(m.colors[i][2], 50, 2);
  }
  EXPECT_GT(facing, m.vertices.size() * 9 / 10);
  // The never-seen voxels behind the wall would have made a second sheet: it was dropped.
  EXPECT_GT(st.dropped_unseen, 0u);
}

TEST(Fusion, RefusesAnEmptyOrHugeVolume) {
  FusionOptions o;
  EXPECT_THROW(fusion_grid(Eigen::AlignedBox3d(), o), ParameterError);
  Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d(2100, 1, 1));
  EXPECT_THROW(fusion_grid(box, o), ParameterError);  // longer than fusion.max_extent_m
  o.voxel_m = 0.002;
  o.max_extent_m = 100;
  box = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d(6, 2, 2));
  EXPECT_THROW(TsdfVolume(fusion_grid(box, o), tsdf_options(o)), ParameterError);  // > 1.8 GB
}

TEST(Fusion, MeshPlyHasColoursAndNormals) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.colors = {{{255, 0, 0}}, {{0, 255, 0}}, {{0, 0, 255}}};
  m.triangles = {{{0, 1, 2}}};
  IoTempDir tmp;
  write_mesh_ply(tmp.file("m.ply"), m);
  const std::vector<char> bytes = tunnelmap::testing::read_binary_file(tmp.file("m.ply"));
  const std::string text(bytes.begin(), bytes.end());
  const std::size_t end = text.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  for (const char* key : {"binary_little_endian", "element vertex 3", "property float nx",
                          "property uchar red", "element face 1", "list uchar int vertex_indices"})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  EXPECT_EQ(bytes.size(), end + 11 + 3 * (6 * 4 + 3) + (1 + 3 * 4));
}

TEST_F(SimSequence, ExactPosesFromJointsGiveAMeshWithin10mm) {
  const Dataset ds = read_dataset(exact);
  ASSERT_FALSE(ds.frames[0].pose);           // arm datasets carry joints, not poses
  ASSERT_EQ(ds.frames[0].joints.size(), 7u);
  const Parameters p = test_params();
  const FusionResult r = fuse_dataset(ds, p);
  for (const FusedFrame& f : r.frames) EXPECT_EQ(f.pose_source, PoseSource::Kinematics);
  const TriangleMesh mesh = extract_mesh(*r.volume, p.get_int("fusion.min_weight"));
  const MeshAccuracy a = mesh_accuracy(mesh, ground_truth_planes(ds.ground_truth), 0.010);
  std::printf("exact poses: %zu vertices, %.2f %% within 10 mm, median %.2f mm, p95 %.2f mm\n",
              a.vertices, 100 * a.fraction_within, a.median_m * 1e3, a.p95_m * 1e3);
  EXPECT_GT(a.vertices, 20000u);
  EXPECT_GE(a.fraction_within, 0.95);

  // Merged map: one tunnel, the size of the middle plates (W - 2 * 8 mm, H - 2 * 8 mm), with the
  // context tolerance (40 mm) as bound; every pose found it.
  const TunnelMap& m = r.merged.map;
  ASSERT_TRUE(m.detected) << m.reason;
  EXPECT_NEAR(m.width_m, 0.82 - 0.016, 0.040);
  EXPECT_NEAR(m.height_m, 1.30 - 0.016, 0.040);
  EXPECT_GT(std::abs(m.axis_dir.x()), 0.99);  // along the world tunnel axis
  EXPECT_GT(m.up.z(), 0.99);
  ASSERT_EQ(r.merged.poses.size(), 3u);
  for (const PoseGroupStatus& g : r.merged.poses) EXPECT_FALSE(g.rescan) << g.message;
  // Zones continue over the whole merged length: every zone spans extent_min..extent_max.
  const Wall& left = m.wall(WallClass::Left);
  ASSERT_TRUE(left.found);
  ASSERT_GE(left.zones.size(), 2u);
  for (const ZoneRect& z : left.zones)
    EXPECT_NEAR(std::abs(m.axis_dir.dot(z.corners[1] - z.corners[0])),
                m.extent_max_m - m.extent_min_m, 1e-9);
  // The left wall lies at +W/2 - plate in the world (y = 0.402).
  EXPECT_NEAR(-left.offset_m / left.normal.y(), 0.41 - 0.008, 0.02);
}

TEST_F(SimSequence, SagDegradesTheMeshButNotPerFrameDetection) {
  const Parameters p = test_params();
  const Dataset de = read_dataset(exact), ds = read_dataset(sag);
  const FusionResult re = fuse_dataset(de, p), rs = fuse_dataset(ds, p);
  const auto truth = ground_truth_planes(ds.ground_truth);
  const MeshAccuracy ae = mesh_accuracy(extract_mesh(*re.volume, 2), truth);
  const MeshAccuracy as = mesh_accuracy(extract_mesh(*rs.volume, 2), truth);
  std::printf("sag 1 deg/m: %.2f %% within 10 mm (exact %.2f %%), p95 %.1f mm (exact %.1f mm)\n",
              100 * as.fraction_within, 100 * ae.fraction_within, as.p95_m * 1e3, ae.p95_m * 1e3);
  EXPECT_LT(as.fraction_within, ae.fraction_within - 0.05);
  EXPECT_GT(as.p95_m, 2 * ae.p95_m);
  // Per-frame detection runs in the camera frame: sag only tilts the "up" prior by < 1 deg, so
  // every frame still finds the tunnel within the 40 mm accuracy bound of its true size.
  for (const FusedFrame& f : rs.frames) {
    ASSERT_TRUE(f.map.detected) << f.index << " " << f.map.reason;
    EXPECT_NEAR(f.map.width_m, 0.82 - 0.016, 0.040);
    EXPECT_NEAR(f.map.height_m, 1.30 - 0.016, 0.040);
    EXPECT_NEAR(f.map.width_m, re.frames[static_cast<std::size_t>(f.index)].map.width_m, 0.005);
  }
}

// The sparse volume against the dense one on the same datasets: the same accuracy bound and
// a vertex count within 5 %.
TEST_F(SimSequence, SparseMeshMatchesTheDenseMeshOnTheLabAndSagDatasets) {
  // The sparse lattice at the world's origin, as the dense one's voxels are: the two meshes then
  // cut the surface at the same places (a fitted offset moves the sag dataset's blurred walls'
  // mesh by ~3 % within 10 mm either way).
  Parameters p = test_params();
  p.set("fusion.offset_fit_frames", 0);
  FuseSettings dense;
  dense.dense = true;
  for (const std::string& path : {exact, sag}) {
    const Dataset ds = read_dataset(path);
    const auto truth = ground_truth_planes(ds.ground_truth);
    const FusionResult rs = fuse_dataset(ds, p), rd = fuse_dataset(ds, p, dense);
    ASSERT_TRUE(rs.volume && !rs.dense_volume && rd.dense_volume && !rd.volume);
    const TriangleMesh ms = extract_mesh(*rs.volume, 2), md = extract_mesh(*rd.dense_volume, 2);
    const MeshAccuracy as = mesh_accuracy(ms, truth), ad = mesh_accuracy(md, truth);
    std::printf("%s: sparse %zu vertices, %.2f %% within 10 mm, %zu KiB; dense %zu vertices, "
                "%.2f %%, %zu KiB\n", path == exact ? "exact" : "sag", ms.vertices.size(),
                100 * as.fraction_within, rs.volume->memory_bytes() >> 10, md.vertices.size(),
                100 * ad.fraction_within, rd.dense_volume->memory_bytes() >> 10);
    EXPECT_NEAR(double(ms.vertices.size()), double(md.vertices.size()), 0.05 * double(md.vertices.size()));
    EXPECT_NEAR(as.fraction_within, ad.fraction_within, 0.002);  // same lattice: nearly the same mesh
    EXPECT_NEAR(as.p95_m, ad.p95_m, 0.1 * ad.p95_m + 0.0005);
    if (path == exact) {
      EXPECT_GE(as.fraction_within, 0.95);  // the bound the dense mesh meets
    }
    EXPECT_LT(rs.volume->memory_bytes(), rd.dense_volume->memory_bytes());
    // At the defaults (the offset fitted) the mesh keeps the dense mesh's size and bounds.
    const FusionResult fitted = fuse_dataset(ds, test_params());
    const TriangleMesh mf = extract_mesh(*fitted.volume, 2);
    const MeshAccuracy af = mesh_accuracy(mf, truth);
    std::printf("%s, offset fitted: %zu vertices, %.2f %% within 10 mm\n", path == exact ? "exact" : "sag",
                mf.vertices.size(), 100 * af.fraction_within);
    EXPECT_NEAR(double(mf.vertices.size()), double(md.vertices.size()), 0.05 * double(md.vertices.size()));
    EXPECT_NEAR(af.fraction_within, ad.fraction_within, 0.05);
    if (path == exact) { EXPECT_GE(af.fraction_within, 0.95); }
  }
}

TEST(MultiScanMap, PoseWithoutDetectionAsksToMoveAndRescan) {
  TunnelMap ok;
  ok.detected = true;
  ok.status = TunnelStatus::Ok;
  ok.width_m = 0.8;
  ok.height_m = 1.2;
  ok.axis_dir = Eigen::Vector3d::UnitZ();  // camera frame: looking along the tunnel
  ok.up = -Eigen::Vector3d::UnitY();
  ok.extent_min_m = 0.5;
  ok.extent_max_m = 2.0;
  TunnelMap bad;
  bad.status = TunnelStatus::TooFewPlanes;
  bad.reason = "2 planes detected, at least 4 needed";
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // camera z -> world x, camera y -> world -z
  std::vector<ScanInput> scans{{ok, T, 0}, {bad, T, 1}, {bad, T, 2}};
  Eigen::Isometry3d T2 = T;
  T2.translation() = Eigen::Vector3d(1.0, 0, 0);  // a second pose 1 m further along
  scans.push_back({ok, T2, 3});
  const std::vector<int> groups{0, 1, 1, 2};
  const MultiScanMap m = merge_scans(scans, groups);
  ASSERT_EQ(m.poses.size(), 3u);
  EXPECT_FALSE(m.poses[0].rescan);
  EXPECT_TRUE(m.poses[1].rescan);
  EXPECT_EQ(m.poses[1].status, "too_few_planes");
  EXPECT_EQ(m.poses[1].message.rfind("move and rescan: too_few_planes", 0), 0u);
  EXPECT_EQ(m.frames_merged, 2);
  EXPECT_NEAR(m.map.axis_dir.x(), 1.0, 1e-12);
  EXPECT_NEAR(m.map.up.z(), 1.0, 1e-12);
  EXPECT_NEAR(m.map.extent_max_m - m.map.extent_min_m, 2.5, 1e-9);  // 0.5..2.0 and 1.5..3.0
  // No frame detected at all: no map, every pose rescans.
  const MultiScanMap none = merge_scans({{bad, T, 0}}, {0});
  EXPECT_FALSE(none.map.detected);
  EXPECT_TRUE(none.poses[0].rescan);
}

TEST(MultiScanMap, TransformMapKeepsPlanesConsistent) {
  TunnelMap m;
  Wall& w = m.wall(WallClass::Left);
  w.found = true;
  w.normal = Eigen::Vector3d(1, 0, 0);
  w.offset_m = 0.4;  // x = -0.4
  w.clusters = {{0.4, 1, 100}};
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, 1, 0.3).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(1, -2, 3);
  const TunnelMap t = transform_map(m, T);
  const Eigen::Vector3d p = T * Eigen::Vector3d(-0.4, 0.3, 0.7);  // a point on the wall
  EXPECT_NEAR(t.wall(WallClass::Left).normal.dot(p) + t.wall(WallClass::Left).offset_m, 0, 1e-12);
  EXPECT_NEAR(t.wall(WallClass::Left).clusters[0].offset_m, t.wall(WallClass::Left).offset_m, 1e-12);
  Eigen::Isometry3d moved = T;
  moved.translation() += Eigen::Vector3d(0.2, 0, 0);
  EXPECT_EQ(group_poses({T, T, moved, moved, T}, 0.05), (std::vector<int>{0, 0, 1, 1, 2}));
}

TEST_F(SimSequence, CliFuseWritesMeshMapAndJson) {
  IoTempDir tmp;
  const auto r = tunnelmap::testing::run_cli(
      "fuse " + exact + " --set fusion.voxel_mm=12 --mesh " + tmp.file("m.ply") + " --map " +
      tmp.file("map.ply") + " --json " + tmp.file("f.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("pose 2 (frames 4-5): ok"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(tunnelmap::testing::slurp(tmp.file("f.json")));
  EXPECT_EQ(j["frames"][0]["pose_source"], "joints");
  EXPECT_GE(j["ground_truth_accuracy"]["fraction_within_10mm"].get<double>(), 0.95);
  EXPECT_TRUE(std::filesystem::file_size(tmp.file("m.ply")) > 100000);
  EXPECT_TRUE(std::filesystem::exists(tmp.file("map.ply")));
  // A dataset frame with neither pose nor joints: exit 3, one line naming dataset.json.
  const auto bad = tunnelmap::testing::run_cli("fuse " + tmp.file("nothing") + " --quiet");
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_EQ(tunnelmap::testing::count_lines(bad.err), 1);
  // The memory the sparse volume used.
  const nlohmann::json& v = j["volume"];
  EXPECT_EQ(v["kind"], "sparse");
  EXPECT_EQ(v["voxels"].get<std::size_t>(), v["blocks"].get<std::size_t>() * 512);
  EXPECT_GT(v["bytes"].get<std::size_t>(), v["voxels"].get<std::size_t>() * 10);
}

// The pieces of --mesh-per-compartment together hold exactly the single mesh's vertices.
TEST_F(SimSequence, CliMeshPiecesTogetherEqualTheSingleMesh) {
  IoTempDir tmp;
  const std::string common = "fuse " + exact + " --quiet --set fusion.voxel_mm=12 --no-pose-refinement";
  const auto one = tunnelmap::testing::run_cli(common + " --mesh " + tmp.file("m.ply"));
  ASSERT_EQ(one.exit_code, 0) << one.err;
  // The lab dataset knows no diaphragms: the piece length is needed.
  const auto none = tunnelmap::testing::run_cli(common + " --mesh-per-compartment " + tmp.file("p0"));
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("--piece-length"), std::string::npos) << none.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.file("p0")));
  const auto cut = tunnelmap::testing::run_cli(common + " --mesh-per-compartment " + tmp.file("p") +
                                               " --piece-length 0.4");
  ASSERT_EQ(cut.exit_code, 0) << cut.err;
  const nlohmann::json index = nlohmann::json::parse(tunnelmap::testing::slurp(tmp.file("p/pieces.json")));
  EXPECT_EQ(index["cut_by"], "length");
  ASSERT_GE(index["pieces"].size(), 3u);
  auto key = [](const Eigen::Vector3f& v) {
    return std::array<long, 3>{std::lround(v.x() * 1e4), std::lround(v.y() * 1e4), std::lround(v.z() * 1e4)};
  };
  const PlyMesh whole = read_ply_mesh(tmp.file("m.ply"));
  std::set<std::array<long, 3>> single, together;
  for (const Eigen::Vector3f& v : whole.vertices) single.insert(key(v));
  std::size_t triangles = 0;
  double last_from = -1e9, last_to = -1e9;
  for (const nlohmann::json& piece : index["pieces"]) {
    const PlyMesh m = read_ply_mesh(tmp.file("p/" + piece["file"].get<std::string>()));
    EXPECT_EQ(m.vertices.size(), piece["vertices"].get<std::size_t>());
    triangles += m.triangles.size();
    for (const Eigen::Vector3f& v : m.vertices) together.insert(key(v));
    EXPECT_LE(piece["from_m"].get<double>(), piece["to_m"].get<double>());
    EXPECT_GE(piece["from_m"].get<double>(), last_from);  // in station order
    EXPECT_GE(piece["to_m"].get<double>(), last_to);
    last_from = piece["from_m"].get<double>();
    last_to = piece["to_m"].get<double>();
  }
  EXPECT_EQ(triangles, whole.triangles.size());
  EXPECT_EQ(together, single);
}
