// The cell-based growing order (grow.cell_px): cell fits from moments, planes found without
// per-pixel normals, and a zone plate's 8 mm step kept apart from its edge band.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>

#include "tests/support/family_girder.h"
#include "core/pipeline/pipeline.h"
#include "core/planes/cell_fits.h"
#include "core/planes/cell_moments_avx2.h"
#include "core/planes/plane_growing.h"
#include "core/sim/tunnel_simulator.h"
#include "core/util/build_paths.h"
#include "tests/core/planes/hand_cloud.h"

using namespace tunnelmap;
using tunnelmap::testing::hand_cloud;

namespace {

// A camera looking at a wall 2 m away whose right part (u >= step_u) stands `step_m` proud.
OrganizedCloud stepped_wall(int w, int h, int step_u, double step_m) {
  OrganizedCloud c = hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const double z = 2.0 - (u >= step_u ? step_m : 0.0);
    p = Eigen::Vector3f(static_cast<float>((u - w / 2.0) / 570.0 * z), static_cast<float>((v - h / 2.0) / 570.0 * z),
                        static_cast<float>(z));
  });
  c.intrinsics.fx = c.intrinsics.fy = 570.0;
  c.intrinsics.cx = w / 2.0, c.intrinsics.cy = h / 2.0;
  return c;
}

// Angle (radians) between a normal and the camera axis, either way round.
double tilt_from_z(const Eigen::Vector3d& n) { return std::acos(std::min(1.0, std::abs(n.z()))); }

}  // namespace

TEST(CellFits, SmallestEigenvectorIsThePlaneNormal) {
  // Points spread in x and y, none in z: the normal is z, whatever the spread.
  const double s[6] = {4.0, 0.5, 0.0, 2.0, 0.0, 0.0};
  Eigen::Vector3d n;
  ASSERT_TRUE(smallest_eigenvector(s, n));
  EXPECT_NEAR(std::abs(n.z()), 1.0, 1e-12);
  const double line[6] = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // collinear points: no unique normal
  EXPECT_FALSE(smallest_eigenvector(line, n));
}

TEST(CellFits, TiltedPlaneCellsFitExactlyAndStepCellsDoNot) {
  // A plane tilted 30 degrees about y; moments taken about a point inside each cell.
  const double t = 30.0 * M_PI / 180.0;
  OrganizedCloud c = hand_cloud(32, 16, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const double x = (u - 16) * 0.004, y = (v - 8) * 0.004;
    p = Eigen::Vector3f(static_cast<float>(x), static_cast<float>(y), static_cast<float>(3.0 + std::tan(t) * x));
  });
  c.points[c.index(3, 3)] = tunnelmap::testing::no_normal();  // an invalid pixel is skipped
  CellGrid grid;
  compute_cell_fits(c, 8, 32, 0.001, grid);
  ASSERT_EQ(grid.cols, 4);
  ASSERT_EQ(grid.rows, 2);
  EXPECT_EQ(grid.cells[0].count, 63);
  for (const CellFit& f : grid.cells) {
    EXPECT_TRUE(f.planar);
    EXPECT_NEAR(f.normal.dot(Eigen::Vector3d(-std::sin(t), 0.0, std::cos(t))), -1.0, 1e-5);  // faces the camera
    EXPECT_LT(std::sqrt(f.mse), 1e-5);
  }
  // 8 mm step through the middle of each cell: not planar at a 1 mm RMS limit.
  const OrganizedCloud stepped = stepped_wall(32, 16, 4, 0.008);
  compute_cell_fits(stepped, 8, 32, 0.001, grid);
  EXPECT_FALSE(grid.cells[0].planar);
  EXPECT_TRUE(grid.cells[1].planar);
}

TEST(CellFits, ACellWithoutItsCentrePixelIsFittedAboutAnotherOfItsPoints) {
  // The moments are taken about a point of the cell: its centre, else the first valid pixel.
  // Here the centre and the first three rows and a half are invalid.
  OrganizedCloud c = stepped_wall(16, 8, 1000, 0.0);
  for (int v = 0; v < 8; ++v)
    for (int u = 0; u < 8; ++u)
      if (v < 3 || (v == 3 && u < 5) || (u == 4 && v == 4)) c.points[c.index(u, v)] = tunnelmap::testing::no_normal();
  CellGrid grid;
  compute_cell_fits(c, 8, 32, 0.001, grid);
  ASSERT_EQ(grid.cells.size(), 2u);
  EXPECT_EQ(grid.cells[0].count, 64 - 24 - 5 - 1);
  EXPECT_EQ(grid.cells[1].count, 64);
  for (const CellFit& f : grid.cells) {
    EXPECT_TRUE(f.planar);
    EXPECT_NEAR(std::abs(f.normal.z()), 1.0, 1e-6);
    EXPECT_NEAR(f.mean.z(), 2.0, 1e-6);
  }
}

TEST(CellGrowing, StepAlongACellBorderSplitsTheWallAndEveryPixelIsLabelled) {
  // The step falls exactly on a cell border (u = 80): no cell straddles it, and the 8 mm offset
  // passes the eq. 2 distance test (15 mm); the continuity test still keeps the two apart.
  const OrganizedCloud c = stepped_wall(160, 120, 80, 0.008);
  GrowOptions o;
  o.cell_px = 8;
  const PlaneSegments planes = extract_planes(c, o);
  ASSERT_EQ(planes.planes.size(), 2u);
  int left = 0;
  for (const PlaneSegment& p : planes.planes) {
    EXPECT_NEAR(std::abs(p.normal.z()), 1.0, 1e-6);
    EXPECT_EQ(p.points, 80 * 120);
    // Offsets 2.000 m and 1.992 m, to a tenth of a millimetre.
    const double off = std::abs(p.offset_m);
    EXPECT_TRUE(std::abs(off - 2.0) < 1e-4 || std::abs(off - 1.992) < 1e-4) << off;
    left += std::abs(off - 2.0) < 1e-4;
  }
  EXPECT_EQ(left, 1);
  for (int v = 0; v < 120; ++v)
    for (int u = 0; u < 160; ++u) {
      const int id = planes.labels[c.index(u, v)];
      ASSERT_GT(id, 0);
      EXPECT_EQ(std::abs(std::abs(planes.planes[id - 1].offset_m) - 2.0) < 1e-4, u < 80) << u << "," << v;
    }
  // Area: the wall is 160 x 120 pixels at about 2 m, (160 * 2 / 570) * (120 * 2 / 570) m^2.
  double area = 0.0;
  for (const PlaneSegment& p : planes.planes) area += p.area_m2;
  EXPECT_NEAR(area, (160 * 2.0 / 570) * (120 * 2.0 / 570), 0.01);
}

TEST(CellGrowing, ReadsNoNormalsAndPlanesCliSkipsThem) {
  OrganizedCloud c = stepped_wall(64, 48, 1000, 0.0);  // one flat wall
  c.normals.clear();
  GrowOptions o;
  o.cell_px = 8;
  EXPECT_FALSE(needs_point_normals(o));
  const PlaneSegments planes = extract_planes(c, o);
  ASSERT_EQ(planes.planes.size(), 1u);
  EXPECT_EQ(planes.planes[0].points, 64 * 48);
  EXPECT_FALSE(planes.planes[0].contour.empty());
  o.cell_px = 0;
  EXPECT_TRUE(needs_point_normals(o));
}

TEST(CellFits, BlockNormalsAreSharperOnAPlaneAndStayTheCellsOwnAcrossAStep) {
  // A wall 2 m away with 2 mm Gaussian depth noise: the 3x3 block's normal is far closer to the
  // truth than a single cell's, and its standard error says so.
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.002f);
  OrganizedCloud c = hand_cloud(48, 48, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const float z = 2.0f + noise(rng);
    p = Eigen::Vector3f((u - 24) / 570.0f * z, (v - 24) / 570.0f * z, z);
  });
  CellGrid grid;
  compute_cell_fits(c, 8, 32, 0.0075, grid);
  smooth_cell_normals(grid);
  double own = 0, block = 0;
  int interior = 0;
  for (int cv = 1; cv + 1 < grid.rows; ++cv)
    for (int cu = 1; cu + 1 < grid.cols; ++cu) {
      const CellFit& f = grid.cells[grid.index(cu, cv)];
      ASSERT_TRUE(f.planar);
      own += tilt_from_z(f.normal);
      block += tilt_from_z(f.block_normal);
      EXPECT_LT(f.block_se, 0.5 * f.normal_se);
      ++interior;
    }
  ASSERT_EQ(interior, 16);
  EXPECT_LT(block, 0.4 * own) << "mean tilt, cell " << own / interior << " rad, block " << block / interior;
  // An exact wall with an 8 mm step at u = 24 (a cell border): the cells beside the step keep
  // their own (exact) normals; one plane through both sides would tilt.
  const OrganizedCloud stepped = stepped_wall(48, 48, 24, 0.008);
  compute_cell_fits(stepped, 8, 32, 0.0075, grid);
  smooth_cell_normals(grid);
  for (const CellFit& f : grid.cells) EXPECT_NEAR(std::abs(f.block_normal.z()), 1.0, 1e-6);
}

TEST(CellFits, Avx2MomentsMatchTheSseOnesToFloatRounding) {
  if (!cell_moments_avx2_available()) GTEST_SKIP() << "no AVX2 on this CPU";
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
  OrganizedCloud c = hand_cloud(37, 21, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const float z = 1.5f + 0.002f * u + jitter(rng);
    p = Eigen::Vector3f((u - 18) / 570.0f * z, (v - 10) / 570.0f * z, z);
  });
  c.points[c.index(9, 4)] = tunnelmap::testing::no_normal();
  const Eigen::Vector3f ref = c.points[c.index(12, 8)];
  // A cell of 8 columns, one of 13 (a tail) and one of 37 (the whole row).
  const int boxes[3][4] = {{8, 0, 16, 8}, {3, 2, 16, 19}, {0, 0, 37, 21}};
  for (const auto& b : boxes) {
    double sse[11], avx[11];
    force_sse_cell_moments(true);
    cell_moments(c, b[0], b[1], b[2], b[3], ref, sse);
    force_sse_cell_moments(false);
    cell_moments(c, b[0], b[1], b[2], b[3], ref, avx);
    EXPECT_EQ(avx[0], sse[0]);
    for (int k = 1; k < 11; ++k) EXPECT_NEAR(avx[k], sse[k], 1e-5 * (std::abs(sse[k]) + 1e-3)) << "moment " << k;
  }
}

namespace {

// Three fronto-parallel walls side by side at 1.0, 2.0 and 3.5 m (each a third of the width),
// with Gaussian depth noise of sigma = 1 mm * z^2: 1, 4 and 12.25 mm.
OrganizedCloud walls_at_three_ranges(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> unit(0.0f, 1.0f);
  OrganizedCloud c = hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const float wall = u < w / 3 ? 1.0f : u < 2 * w / 3 ? 2.0f : 3.5f;
    const float z = wall + 0.001f * wall * wall * unit(rng);
    p = Eigen::Vector3f((u - w / 2.0f) / 570.0f * z, (v - h / 2.0f) / 570.0f * z, z);
  });
  c.intrinsics.fx = c.intrinsics.fy = 570.0;
  c.intrinsics.cx = w / 2.0, c.intrinsics.cy = h / 2.0;
  return c;
}

}  // namespace

TEST(CellFits, NoiseBoundFollowsTheRangeSquared) {
  const OrganizedCloud c = walls_at_three_ranges(192, 96, 11);
  CellGrid grid;
  // Without a noise bound only the walls whose noise is within 4 mm RMS are planar.
  compute_cell_fits(c, 8, 32, 0.004, grid);
  EXPECT_EQ(grid.noise_per_m2, 0.0);
  EXPECT_TRUE(grid.cells[grid.index(2, 5)].planar);    // 1 m
  EXPECT_FALSE(grid.cells[grid.index(20, 5)].planar);  // 3.5 m: 12 mm of noise
  // The estimate is the cells' lower-quartile RMS / z^2: about 1 mm / m^2 here (a cell's own
  // fit takes 3 of its 64 degrees of freedom, so a little less).
  compute_cell_fits(c, 8, 32, 0.004, grid, 2.5);
  EXPECT_NEAR(grid.noise_per_m2, 0.00095, 0.0001);
  int far = 0, far_planar = 0;
  for (const CellFit& f : grid.cells) {
    EXPECT_TRUE(f.fitted);
    if (f.mean.z() < 1.5) {
      EXPECT_TRUE(f.quiet);
    }
    if (f.mean.z() > 3.0) ++far, far_planar += f.planar && !f.quiet;
  }
  EXPECT_EQ(far_planar, far);
  smooth_cell_normals(grid);
  // The far cells keep their planarity through block normals, which are within 4 degrees of
  // the truth and several times closer than the cells' own normals.
  double own = 0, block = 0;
  int n = 0;
  for (int cv = 1; cv + 1 < grid.rows; ++cv)
    for (int cu = 17; cu + 1 < grid.cols; ++cu) {
      const CellFit& f = grid.cells[grid.index(cu, cv)];
      ASSERT_TRUE(f.planar && f.block_fitted) << cu << "," << cv;
      EXPECT_LT(tilt_from_z(f.block_normal), 4.0 * M_PI / 180.0) << cu << "," << cv;
      own += tilt_from_z(f.normal);
      block += tilt_from_z(f.block_normal);
      ++n;
    }
  ASSERT_EQ(n, 60);
  EXPECT_LT(block, 0.25 * own) << "mean tilt, cell " << own / n << " rad, block " << block / n;
}

TEST(CellFits, TheNoiseAlongTheRaysIsMeasuredOnCellsThatFaceTheCamera) {
  // Depth noise of 0.8 mm at 1 m, growing with z^2, along the rays. The left half of the view
  // is a wall 0.4 m to the side, seen at 74-90 degrees of incidence; the right half a plate 2 m
  // ahead. The wall shows a fraction of the noise about its plane, and the frame's noise, from
  // all cells, is well below the sensor's; the noise along the rays, from the cells that face
  // the camera, is the sensor's. Without the plate no cell faces the camera enough to tell.
  const double c = 0.0008;
  for (const bool with_plate : {true, false}) {
    std::mt19937 rng(3);
    std::normal_distribution<float> unit(0.0f, 1.0f);
    const int w = 320, h = 96;
    const OrganizedCloud cloud = hand_cloud(w, h, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
      const float x = (u - w / 2.0f) / 570.0f, y = (v - h / 2.0f) / 570.0f;
      float z = 0.0f;
      if (x < 0.0f) z = std::min(4.0f, -0.4f / x);
      else if (with_plate) z = 2.0f;
      else return;
      z += static_cast<float>(c) * z * z * unit(rng);
      p = Eigen::Vector3f(x * z, y * z, z);
    });
    CellGrid grid;
    compute_cell_fits(cloud, 8, 32, 0.004, grid, 2.5);
    SCOPED_TRACE(with_plate ? "with the plate" : "the wall alone");
    EXPECT_LT(grid.noise_per_m2, 0.5 * c);
    if (with_plate) {
      EXPECT_NEAR(grid.axial_noise_per_m2, c, 0.1 * c);
    } else {
      EXPECT_EQ(grid.axial_noise_per_m2, 0.0);
    }
  }
}

TEST(CellFits, RoughCellsNearbyStayNonPlanarUnderTheNoiseBound) {
  // A wall at 1 m whose right half is rough (uniform +-15 mm). An 8-pixel cell at 1 m spans
  // only 4 mm RMS across, so its least-squares plane leaves about that much whatever the
  // roughness: above the 2 mm bound and 2.5 times the 1 mm noise at 1 m, so neither bound
  // makes it planar.
  std::mt19937 rng(5);
  std::normal_distribution<float> noise(0.0f, 0.001f);
  std::uniform_real_distribution<float> rough(-0.015f, 0.015f);
  const OrganizedCloud c = hand_cloud(128, 64, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    const float depth_noise = noise(rng);  // drawn before the roughness: operand order is the compiler's
    const float z = 1.0f + depth_noise + (u >= 64 ? rough(rng) : 0.0f);
    p = Eigen::Vector3f((u - 64) / 570.0f * z, (v - 32) / 570.0f * z, z);
  });
  CellGrid grid;
  compute_cell_fits(c, 8, 32, 0.002, grid, 2.5);
  smooth_cell_normals(grid);
  for (int cv = 0; cv < grid.rows; ++cv)
    for (int cu = 0; cu < grid.cols; ++cu) EXPECT_EQ(grid.cells[grid.index(cu, cv)].planar, cu < 8) << cu << "," << cv;
}

TEST(CellGrowing, FarWallNoisierThanHalfEpsilonIsOnePlane) {
  // epsilon 8 mm (the lab preset): the 3.5 m wall's 12 mm noise puts every one of its cells
  // above epsilon / 2, yet it is one plane with the wall's normal and offset, as are the others.
  const OrganizedCloud c = walls_at_three_ranges(192, 96, 13);
  GrowOptions o;
  o.cell_px = 8;
  o.distance_m = 0.008;
  const PlaneSegments planes = extract_planes(c, o);
  ASSERT_EQ(planes.planes.size(), 3u);
  for (const PlaneSegment& p : planes.planes) {
    EXPECT_GT(std::abs(p.normal.z()), std::cos(1.0 * M_PI / 180.0));
    const double off = std::abs(p.offset_m);
    const double wall = off < 1.5 ? 1.0 : off < 2.75 ? 2.0 : 3.5;
    EXPECT_NEAR(off, wall, 0.003) << off;
    // Each wall is 64 x 96 pixels; the far one loses at most its border pixels beyond epsilon.
    EXPECT_GE(p.points, wall < 3 ? 64 * 96 * 0.97 : 64 * 96 * 0.8) << "wall at " << wall << " m";
  }
}

TEST(CellGrowing, PlateStepsCutNoStripsOfTheirOwn) {
  // A field frame looking down the floor: its 6-12 mm plate steps run along the tunnel, and the
  // cells they cross used to grow two strips of their own there (1,709 and 1,875 pixels, each
  // half middle plate and half edge band, 13 degrees off the floor). Those cells are left to the
  // per-pixel assignment now: every plane lies mostly on one plate, and the plates keep their
  // pixels.
  Parameters params;
  params.load_json_file(std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets/field.json");
  params.set_from_string("grow.cell_px=8");
  SimConfig config = SimConfig::from_preset("field");
  config.seed = 102;
  const TunnelSimulator sim(config);
  const SimFrame frame = sim.render(15);
  FrameResult r;
  Pipeline(params).run(frame.frame, r);
  ASSERT_GT(r.planes.planes.size(), 10u);
  std::map<int, std::map<int, long>> on_surface;  // plane id -> surface id -> pixels
  for (std::size_t k = 0; k < r.planes.labels.size(); ++k)
    if (r.planes.labels[k] > 0) ++on_surface[r.planes.labels[k]][frame.surface_id[k]];
  for (const PlaneSegment& p : r.planes.planes) {
    long all = 0, most = 0;
    for (const auto& [surface, pixels] : on_surface[p.id]) all += pixels, most = std::max(most, pixels);
    EXPECT_GT(2 * most, all) << "plane " << p.id << " of " << all << " pixels";
  }
  // The floor's plates keep at least 95 % of their valid pixels labelled (measured 96.9-97.6 %,
  // and 96.5-97.3 % with the strips).
  for (const char* name : {"bottom/middle", "bottom/edge_left", "bottom/edge_right"}) {
    long valid = 0, labelled = 0;
    for (std::size_t k = 0; k < frame.surface_id.size(); ++k) {
      const SimSurface* s = sim.surface(frame.surface_id[k]);
      if (!s || s->name != name || !OrganizedCloud::valid(r.cloud.points[k])) continue;
      ++valid;
      labelled += r.planes.labels[k] > 0;
    }
    ASSERT_GT(valid, 2000) << name;
    EXPECT_GE(static_cast<double>(labelled) / valid, 0.95) << name;
  }
}

// 1.8 m from a diaphragm, the camera 7 cm under the roof: through the manhole the end wall
// shows 1.2 m behind the plate. Along the rim the sensor's flying pixels lie on the rays
// between the two, and the pixels beside the rim have 5 x 5 windows that straddle the jump.
// Neither makes a plane: flying pixels lined up into planes through the camera (half plate,
// half end wall, 0.3-0.8 degrees from edge-on), and the edge-on pass grew strips of plate
// pixels along the rim whose planes were tilted 20-80 degrees off the plate.
TEST(CellGrowing, AManholeRimMakesNoPlaneOfItsOwn) {
  SimConfig config = SimConfig::from_preset("lab");
  config.frames = 3;
  config.diaphragm_x_m = {5.0};
  SimWalk walk;
  walk.start_x_m = walk.end_x_m = 3.2;
  walk.stops = 1;
  walk.pose = SimCameraPose{0.0, 0.95, 0.0, 0.0, 0.0};
  config.walk = walk;
  const TunnelSimulator sim(config);
  int plate = 0, end = 0;
  for (const SimSurface& s : sim.surfaces()) {
    if (s.wall == "diaphragm") plate = s.id;
    if (s.wall == "end") end = s.id;
  }
  ASSERT_TRUE(plate > 0 && end > 0);
  int checked = 0, tilted_strips = 0;
  for (const double eps_mm : {15.0, 8.0}) {  // the paper's epsilon and the lab preset's
    Parameters params;
    params.set("grow.cell_px", 8);
    params.set("grow.distance_mm", eps_mm);
    const Pipeline pipeline(params);
    for (int i = 0; i < config.frames; ++i) {
      const SimFrame frame = sim.render(i);
      const Eigen::Vector3d plate_normal =
          -(frame.frame.pose->linear().transpose() * Eigen::Vector3d::UnitX());  // facing the camera
      FrameResult r;
      pipeline.run(frame.frame, r);
      std::map<int, std::map<int, long>> on_surface;  // plane id -> surface id -> pixels
      for (std::size_t k = 0; k < r.planes.labels.size(); ++k)
        if (r.planes.labels[k] > 0) ++on_surface[r.planes.labels[k]][frame.surface_id[k]];
      for (const PlaneSegment& p : r.planes.planes) {
        long all = 0;
        for (const auto& [surface, pixels] : on_surface[p.id]) all += pixels;
        const long on_plate = on_surface[p.id][plate], on_end = on_surface[p.id][end];
        SCOPED_TRACE("epsilon " + std::to_string(eps_mm) + " mm, frame " + std::to_string(i) + ", plane " +
                     std::to_string(p.id) + " of " + std::to_string(all) + " pixels");
        EXPECT_FALSE(10 * on_plate > all && 10 * on_end > all) << on_plate << " on the plate, " << on_end << " behind it";
        if (10 * on_plate < 9 * all) continue;
        const bool along_the_plate = std::abs(p.normal.dot(plate_normal)) > std::cos(10.0 * M_PI / 180.0);
        if (p.edge_on) {
          tilted_strips += !along_the_plate;
        } else {
          EXPECT_TRUE(along_the_plate);
          ++checked;
        }
      }
    }
  }
  EXPECT_GE(checked, 6);  // the plate itself, in every frame
  // Measured: 6 over the six runs, 25 without the edge-on pass's receding test. The 6 left lie
  // where the roof meets the plate: roof pixels among them spread along the sight line.
  std::printf("edge-on strips of plate pixels tilted off the plate: %d\n", tilted_strips);
  EXPECT_LE(tilted_strips, 6);
}

// Girder 5 of the girder family (seed 1): frames 20 and 21 stand 3.3 m before a diaphragm
// and see its face across the view. There the structured-light noise along the rays is about
// 20 mm, in terraces of 32 mm, and a cell facing the camera shows all of it. The walls, seen at
// grazing incidence, show a fraction of it, and the frame's noise estimated from them held the
// plate's cells to 20 mm RMS: its blocks measured 22-27 mm, and the plate made no plane (2 %
// of its pixels went to the walls' planes). Now one plane takes most of it, along its normal.
TEST(CellGrowing, APlateAcrossTheViewIsFoundAtTheRangeWhereItsNoiseExceedsTheWalls) {
  const tunnelmap::testing::FamilyGirder girder(1, 5);
  const TunnelSimulator& sim = girder.sim();
  for (const int i : {20, 21}) {
    SimFrame frame;
    const FrameResult r = girder.detect(i, &frame);
    std::map<int, long> on_plate;  // plane id -> its pixels on a diaphragm
    long valid = 0;
    for (std::size_t k = 0; k < r.planes.labels.size(); ++k) {
      const SimSurface* surface = sim.surface(frame.surface_id[k]);
      if (!surface || surface->wall != "diaphragm" || !OrganizedCloud::valid(r.cloud.points[k])) continue;
      ++valid;
      if (r.planes.labels[k] > 0) ++on_plate[r.planes.labels[k]];
    }
    SCOPED_TRACE("frame " + std::to_string(i));
    ASSERT_GT(valid, 15000);
    long largest = 0, tilted = 0;
    for (const PlaneSegment& p : r.planes.planes) {
      if (2 * on_plate[p.id] < p.points) continue;
      if (std::abs(p.normal.dot(r.map.axis_dir)) < std::cos(10.0 * M_PI / 180.0)) {
        tilted += on_plate[p.id];
        continue;
      }
      largest = std::max(largest, on_plate[p.id]);
    }
    // Measured: 75 % and 83 % in one plane; 2.6 % and 2.0 % in small planes (100-510 pixels)
    // tilted 23-76 degrees off the plate.
    EXPECT_GT(static_cast<double>(largest) / valid, 0.6) << largest << " of " << valid << " plate pixels";
    EXPECT_LT(static_cast<double>(tilted) / valid, 0.05) << tilted << " plate pixels in tilted planes";
  }
}
