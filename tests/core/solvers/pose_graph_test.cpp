// The pose graph with plane landmarks on a synthetic box tunnel (x along the axis, walls at
// y = +-0.45 m, z = 0 and 1.2 m, plates across it every 4 m): patches are exact moments of
// points on the true surfaces, so what the solver returns is the method, not noise.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>
#include <random>

#include "core/solvers/pose_graph.h"

namespace tunnelmap {
namespace {

struct TruePlane {
  Eigen::Vector3d normal;
  double offset;  // n . x = offset
};

// A camera looking along +x (camera z), image-down = -z world.
Eigen::Isometry3d camera_at(double x, double y, double z, double yaw_deg = 0.0) {
  Eigen::Matrix3d look;
  look.col(0) = -Eigen::Vector3d::UnitY();  // camera x: right
  look.col(1) = -Eigen::Vector3d::UnitZ();  // camera y: down
  look.col(2) = Eigen::Vector3d::UnitX();   // camera z: forward
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix() * look;
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

// The exact moments of a grid of points on `plane` over [x0, x1] along the axis and `across`
// (the in-plane direction other than x) between a0 and a1, seen from `T`.
PlanePatch patch_of(const Eigen::Isometry3d& T, int pose, int plane_index, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& along, const Eigen::Vector3d& across, double l0, double l1,
                    double a0, double a1) {
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j)
      pts.push_back(T.inverse() * (origin + along * (l0 + (l1 - l0) * i / 10.0) + across * (a0 + (a1 - a0) * j / 10.0)));
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : pts) c += p;
  c /= double(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : pts) cov += (p - c) * (p - c).transpose();
  cov /= double(pts.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  PlanePatch patch;
  patch.pose = pose;
  patch.plane = plane_index;
  patch.centroid = c;
  for (int k = 1; k < 3; ++k) patch.spread.col(k - 1) = eig.eigenvectors().col(k) * std::sqrt(eig.eigenvalues()[k]);
  patch.sigma_m = 0.001;
  return patch;
}

struct Walk {
  std::vector<Eigen::Isometry3d> truth;
  std::vector<GraphPlane> planes;  // true planes: 4 walls per 1 m band, then the plates
  PoseGraph graph;                 // patches from the truth
};

// Cameras every 0.25 m over 20 m; each sees the walls from 0.5 to 3.5 m ahead in 1 m bands and
// the plates 0.5-5 m ahead (so that some see two plates at once). The walls are one landmark per
// band, as StructureSlam makes them.
Walk make_walk(bool with_plates) {
  Walk w;
  const double half_w = 0.45, h = 1.2;
  const double band = 1.0;
  const int bands = 24;
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  for (int b = 0; b < bands; ++b) {
    w.planes.push_back({Y, half_w});
    w.planes.push_back({-Y, half_w});
    w.planes.push_back({Z, h});
    w.planes.push_back({-Z, 0.0});
  }
  const int first_plate = static_cast<int>(w.planes.size());
  for (int k = 1; k <= 5; ++k) w.planes.push_back({X, 4.0 * k});
  for (int i = 0; i < 80; ++i) {
    const double x = 0.25 * i;
    const Eigen::Isometry3d T = camera_at(x, 0.05 * std::sin(0.3 * i), 0.6 + 0.03 * std::cos(0.2 * i), 2.0 * std::sin(0.1 * i));
    w.truth.push_back(T);
    for (int b = static_cast<int>(std::floor((x + 0.5) / band)); b <= std::min(bands - 1, static_cast<int>(std::floor((x + 3.5) / band))); ++b) {
      const double l0 = std::max<double>(b * band, x + 0.5), l1 = std::min<double>((b + 1) * band, x + 3.5);
      if (l1 - l0 < 0.3) continue;
      w.graph.patches.push_back(patch_of(T, i, 4 * b + 0, Eigen::Vector3d(0, half_w, 0), X, Z, l0, l1, 0.1, h - 0.1));
      w.graph.patches.push_back(patch_of(T, i, 4 * b + 1, Eigen::Vector3d(0, -half_w, 0), X, Z, l0, l1, 0.1, h - 0.1));
      w.graph.patches.push_back(patch_of(T, i, 4 * b + 2, Eigen::Vector3d(0, 0, h), X, Y, l0, l1, -0.35, 0.35));
      w.graph.patches.push_back(patch_of(T, i, 4 * b + 3, Eigen::Vector3d(0, 0, 0), X, Y, l0, l1, -0.35, 0.35));
    }
    if (!with_plates) continue;
    for (int k = 1; k <= 5; ++k) {
      const double ahead = 4.0 * k - x;
      if (ahead < 0.5 || ahead > 5.0) continue;
      w.graph.patches.push_back(patch_of(T, i, first_plate + k - 1, Eigen::Vector3d(4.0 * k, 0, 0), Y, Z, -0.4, 0.4, 0.1, 1.1));
    }
  }
  return w;
}

// Odometry that drifts: a random walk of `mm` and `deg` per square root of metre, position in
// the world frame; the graph starts from the drifted poses.
void add_drifting_odometry(Walk& w, double mm, double deg, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01;
  Eigen::Vector3d dt = Eigen::Vector3d::Zero();
  Eigen::Matrix3d dR = Eigen::Matrix3d::Identity();
  std::vector<Eigen::Isometry3d> drifted;
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    if (i > 0) {
      const double k = std::sqrt((w.truth[i].translation() - w.truth[i - 1].translation()).norm());
      Eigen::Vector3d step, turn;  // drawn in a fixed order (argument order is unspecified)
      for (int a = 0; a < 3; ++a) step[a] = n01(rng);
      for (int a = 0; a < 3; ++a) turn[a] = n01(rng);
      dt += step * mm / 1000.0 * k;
      const Eigen::Vector3d r = turn * deg * M_PI / 180.0 * k;
      dR = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix() * dR;
    }
    Eigen::Isometry3d T = w.truth[i];
    T.linear() = dR * T.linear();
    T.translation() += dt;
    drifted.push_back(T);
  }
  w.graph.poses = drifted;
  w.graph.fixed.assign(drifted.size(), false);
  w.graph.fixed[0] = true;
  w.graph.planes = w.planes;
  for (auto& p : w.graph.planes) p.offset += 0.01;  // the map is not known either
  for (std::size_t i = 1; i < drifted.size(); ++i) {
    GraphOdometry o;
    o.from = static_cast<int>(i - 1);
    o.to = static_cast<int>(i);
    o.relative = drifted[i - 1].inverse() * drifted[i];
    o.world_translation = true;
    o.world_step = drifted[i].translation() - drifted[i - 1].translation();
    const double d = o.world_step.norm();
    o.sigma_m = std::max(mm / 1000.0 * std::sqrt(d), 0.0005);
    o.sigma_rad = std::max(deg * std::sqrt(d), 0.01) * M_PI / 180.0;
    w.graph.odometry.push_back(o);
  }
}

double angle_deg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() * 180.0 / M_PI;
}

// The solution's poses after one rigid alignment with the truth, its rotation the mean of the
// orientations' differences and its translation the mean of the positions' (the map's frame is
// the first pose's, whose view of the walls fixes its orientation only to the patches' precision).
std::vector<Eigen::Isometry3d> aligned(const std::vector<Eigen::Isometry3d>& poses,
                                       const std::vector<Eigen::Isometry3d>& truth) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < poses.size(); ++i) sum += truth[i].linear() * poses[i].linear().transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  Eigen::Isometry3d align = Eigen::Isometry3d::Identity();
  align.linear() = svd.matrixU() * D * svd.matrixV().transpose();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < poses.size(); ++i) t += truth[i].translation() - align.linear() * poses[i].translation();
  align.translation() = t / static_cast<double>(poses.size());
  std::vector<Eigen::Isometry3d> out;
  for (const Eigen::Isometry3d& T : poses) out.push_back(align * T);
  return out;
}

TEST(PoseGraph, ExactPosesAndExactPatchesStayWhereTheyAre) {
  Walk w = make_walk(true);
  add_drifting_odometry(w, 0.0, 0.0, 1);
  const PoseGraphSolution s = solve_pose_graph(w.graph);
  ASSERT_EQ(s.poses.size(), w.truth.size());
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    EXPECT_LT((s.poses[i].translation() - w.truth[i].translation()).norm(), 1e-4) << i;
    EXPECT_LT(angle_deg(s.poses[i].linear(), w.truth[i].linear()), 1e-3) << i;
  }
  // The planes that were seen moved back onto the truth (they started 10 mm off).
  std::vector<bool> seen(w.planes.size(), false);
  for (const PlanePatch& p : w.graph.patches) seen[static_cast<std::size_t>(p.plane)] = true;
  for (std::size_t k = 0; k < w.planes.size(); ++k)
    if (seen[k]) {
      EXPECT_NEAR(s.planes[k].offset, w.planes[k].offset, 1e-4) << k;
    }
}

TEST(PoseGraph, WallsAndPlatesTakeOutTheDriftAcrossTheAxisAndAlongIt) {
  Walk w = make_walk(true);
  add_drifting_odometry(w, 10.0, 0.2, 7);
  double drift_mm = 0.0, drift_deg = 0.0;
  const std::vector<Eigen::Isometry3d> given = aligned(w.graph.poses, w.truth);
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    drift_mm = std::max(drift_mm, 1000 * (given[i].translation() - w.truth[i].translation()).norm());
    drift_deg = std::max(drift_deg, angle_deg(given[i].linear(), w.truth[i].linear()));
  }
  ASSERT_GT(drift_mm, 20.0);  // the drift is there to take out, even after alignment
  ASSERT_GT(drift_deg, 0.5);
  const PoseGraphSolution s = solve_pose_graph(w.graph);
  EXPECT_TRUE(s.converged);
  const std::vector<Eigen::Isometry3d> poses = aligned(s.poses, w.truth);
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();
  double worst_deg = 0.0;
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    const Eigen::Vector3d e = poses[i].translation() - w.truth[i].translation();
    // Patches good to 1 mm against odometry that drifted by 72 mm and 1.3 deg (after alignment;
    // measured: 4.5 and 1.4 mm across, 0.8 mm along, 0.09 deg at worst).
    EXPECT_LT(std::abs(e.y()) * 1000, 6.0) << i;  // walls: across the axis
    EXPECT_LT(std::abs(e.z()) * 1000, 6.0) << i;
    EXPECT_LT(std::abs(e.x()) * 1000, 3.0) << i;  // plates, some seen two at a time: along it
    EXPECT_LT(angle_deg(poses[i].linear(), w.truth[i].linear()), 0.15) << i;
    worst = worst.cwiseMax(e.cwiseAbs() * 1000);
    worst_deg = std::max(worst_deg, angle_deg(poses[i].linear(), w.truth[i].linear()));
  }
  std::printf("worst after alignment: along %.2f, across %.2f, %.2f mm, %.3f deg (odometry: %.1f mm, %.2f deg)\n",
              worst.x(), worst.y(), worst.z(), worst_deg, drift_mm, drift_deg);
}

TEST(PoseGraph, APlaneOneCameraSeesAsAStripNeitherMovesThePosesNorHoldsTheSolveBack) {
  // A strip of a plate (points on one line) seen by one camera turns freely about the line;
  // it cannot tell any pose anything, and the solve must still converge to the same poses.
  Walk w = make_walk(true);
  add_drifting_odometry(w, 10.0, 0.2, 7);
  const PoseGraphSolution without = solve_pose_graph(w.graph);
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY();
  const int strip = static_cast<int>(w.graph.planes.size());
  w.graph.planes.push_back({Eigen::AngleAxisd(5.0 * M_PI / 180.0, Y) * X, 8.3});
  w.graph.patches.push_back(patch_of(w.truth[20], 20, strip, Eigen::Vector3d(8.0, 0, 0), Y, Eigen::Vector3d::UnitZ(), -0.4, 0.4, 0.6, 0.6));
  const PoseGraphSolution with = solve_pose_graph(w.graph);
  EXPECT_TRUE(with.converged);
  for (std::size_t i = 0; i < w.truth.size(); ++i)
    EXPECT_LT((with.poses[i].translation() - without.poses[i].translation()).norm(), 1e-5) << i;
  // The strip's plane passes through the strip, wherever it turned about it.
  const Eigen::Vector3d on_strip = with.poses[20] * w.graph.patches.back().centroid;
  EXPECT_NEAR(with.planes[static_cast<std::size_t>(strip)].normal.dot(on_strip), with.planes[static_cast<std::size_t>(strip)].offset, 1e-4);
}

TEST(PoseGraph, WithoutPlatesTheAxisIsLeftToOdometryAndReportedDegenerate) {
  Walk w = make_walk(false);
  add_drifting_odometry(w, 10.0, 0.0, 3);
  const PoseGraphSolution s = solve_pose_graph(w.graph);
  for (std::size_t i = 0; i < w.truth.size(); ++i) {
    // Across the axis the walls set the poses; along it they keep the odometry's steps, drift
    // and all (nothing measures it).
    const double along = s.poses[i].translation().x() - s.poses[0].translation().x();
    const double given = w.graph.poses[i].translation().x() - w.graph.poses[0].translation().x();
    EXPECT_NEAR(along, given, 0.5e-3) << i;
  }
  double axial_drift_mm = 0.0;
  for (std::size_t i = 0; i < w.truth.size(); ++i)
    axial_drift_mm = std::max(axial_drift_mm, 1000 * std::abs(w.graph.poses[i].translation().x() - w.truth[i].translation().x()));
  EXPECT_GT(axial_drift_mm, 5.0);
  const Eigen::Matrix<double, 6, 6> H = patch_information(w.graph, s, 10, s.poses[10].translation());
  const double top = H.diagonal().maxCoeff();
  EXPECT_LT(H(3, 3), 1e-6 * top);  // translation along x: no information
  EXPECT_GT(H(4, 4), 1e-3 * top);  // across it: walls
  EXPECT_GT(H(5, 5), 1e-3 * top);
}

// Two stretches of floor either side of a plate, x < 0 seen from pose 0 (held) and x > 0 from
// pose 1 only, whose odometry says it rolled by 1 degree (loosely: 5 degrees). Tied at x = 0
// with or without their roll: the floor beyond the plate, and pose 1 with it, rolls as the
// odometry says unless the roll is tied.
double roll_after_tie_deg(double sigma_rad) {
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(), Z = Eigen::Vector3d::UnitZ();
  const Eigen::Isometry3d A = camera_at(-2.0, 0.0, 0.6), B = camera_at(0.5, 0.0, 0.6);
  PoseGraph g;
  Eigen::Isometry3d rolled = B;
  rolled.linear() = Eigen::AngleAxisd(M_PI / 180.0, X).toRotationMatrix() * B.linear();
  g.poses = {A, rolled};
  g.fixed = {true, false};
  g.planes = {{-Z, 0.0}, {-Z, 0.0}};
  g.patches.push_back(patch_of(A, 0, 0, Eigen::Vector3d::Zero(), X, Y, -1.5, -0.1, -0.4, 0.4));
  g.patches.push_back(patch_of(B, 1, 1, Eigen::Vector3d::Zero(), X, Y, 0.1, 3.0, -0.4, 0.4));
  GraphOdometry o;
  o.from = 0, o.to = 1;
  o.relative = A.inverse() * rolled;
  o.sigma_m = 0.001, o.sigma_rad = 5.0 * M_PI / 180.0;
  g.odometry.push_back(o);
  PlaneContinuity tie;
  tie.a = 0, tie.b = 1, tie.pose = 1;
  tie.point = B.inverse() * Eigen::Vector3d::Zero();
  tie.across = B.linear().transpose() * Y;
  tie.sigma_rad = sigma_rad;
  g.continuities.push_back(tie);
  const PoseGraphSolution s = solve_pose_graph(g);
  return angle_deg(s.poses[1].linear(), B.linear());
}

TEST(PoseGraph, AWallTiedAcrossAPlateDoesNotRollThere) {
  const double free = roll_after_tie_deg(0.0), tied = roll_after_tie_deg(0.05 * M_PI / 180.0);
  EXPECT_NEAR(free, 1.0, 0.05);
  EXPECT_LT(tied, 0.01);
}

TEST(PoseGraph, AnEvenTurnTiedTightlyLeavesATightArcAsItIs) {
  // Three stretches of a wall on a 150 m curve, 4 m apart (1.53 degrees between them), each
  // held by its patch, tied to an even turn at 0.001 degrees: they turn evenly already, and
  // the tie must not pull them straighter (the sum of the normals falls short of the middle
  // one by 1 - cos(1.53 degrees), 0.02 degrees, along it).
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY();
  auto turn = [](double deg) { return Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()); };
  const double step_deg = 4.0 / 150.0 * 180.0 / M_PI;
  PoseGraph g;
  g.poses = {Eigen::Isometry3d::Identity()};
  g.fixed = {true};
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  for (int k = 0; k < 3; ++k) {
    g.planes.push_back(GraphPlane{turn(k * step_deg) * Y, 0.0});
    g.patches.push_back(patch_of(I, 0, k, Eigen::Vector3d::Zero(), turn(k * step_deg) * X, Eigen::Vector3d::UnitZ(), -0.5, 0.5, 0.0, 1.0));
  }
  g.bends.push_back({{{0}, {1}, {2}}, {-0.5, 1.0, -0.5}, 0.001 * M_PI / 180.0});
  const PoseGraphSolution s = solve_pose_graph(g);
  for (int k = 0; k < 3; ++k) {
    const double deg = std::atan2(-s.planes[k].normal.x(), s.planes[k].normal.y()) * 180.0 / M_PI;
    EXPECT_NEAR(deg, k * step_deg, 0.001) << k;
  }
}

TEST(PoseGraph, FourStretchesOfAWallTurnAsATransitionCurveDoes) {
  // Four planes of one wall at x = 0, 1, 2 and 3 m. Patches hold the first, third and fourth
  // at 0, 2 and 4.5 degrees: a heading of 0.5 x^2 degrees, as along a transition curve. The
  // second, seen by nothing, starts at 1.5 degrees (an even turn would put it at 1); the tie
  // puts it on the quadratic through the others, at 0.5 degrees.
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY();
  auto turn = [](double deg) { return Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()); };
  auto wall = [&](double deg) { return GraphPlane{turn(deg) * Y, 0.0}; };
  PoseGraph g;
  g.poses = {Eigen::Isometry3d::Identity()};
  g.fixed = {true};
  g.planes = {wall(0.0), wall(1.5), wall(2.0), wall(4.5)};
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  const double held[] = {0.0, 0.0, 2.0, 4.5};
  for (int k : {0, 2, 3})
    g.patches.push_back(patch_of(I, 0, k, Eigen::Vector3d::Zero(), turn(held[k]) * X, Eigen::Vector3d::UnitZ(), -0.5, 0.5, 0.0, 1.0));
  g.bends.push_back({{{0}, {1}, {2}, {3}}, {-1.0 / 3.0, 1.0, -1.0, 1.0 / 3.0}, 0.05 * M_PI / 180.0});
  const PoseGraphSolution s = solve_pose_graph(g);
  ASSERT_TRUE(s.converged);
  double deg[4];
  for (int k = 0; k < 4; ++k) deg[k] = std::atan2(-s.planes[k].normal.x(), s.planes[k].normal.y()) * 180.0 / M_PI;
  // On the quadratic through the other three as solved (their patches give a little: they
  // are weak against a tie 20 sigmas off at the start), and near where the truth has it.
  EXPECT_NEAR(deg[1], deg[0] / 3.0 + deg[2] - deg[3] / 3.0, 0.002);
  EXPECT_NEAR(deg[1], 0.5, 0.02);
}

// Ten poses 1 m apart along x, odometry between them that pitches the camera by 0.5 degrees
// and turns it by 0.5 degrees a step (each within its uncertainty); no landmarks.
struct TiltedWalk {
  PoseGraph graph;
  std::vector<Eigen::Isometry3d> truth;
};

TiltedWalk tilted_walk() {
  TiltedWalk w;
  Eigen::Isometry3d given = camera_at(0, 0, 1);
  for (int k = 0; k < 10; ++k) {
    w.truth.push_back(camera_at(k, 0, 1));
    w.graph.poses.push_back(given);
    w.graph.fixed.push_back(k == 0);
    if (k == 0) continue;
    const Eigen::Isometry3d measured = Eigen::Translation3d(Eigen::Vector3d(0, 0, 1)) *
                                       Eigen::AngleAxisd(0.5 * M_PI / 180.0, Eigen::Vector3d::UnitX()) *
                                       Eigen::AngleAxisd(0.5 * M_PI / 180.0, Eigen::Vector3d::UnitY());
    GraphOdometry o;
    o.from = k - 1;
    o.to = k;
    o.relative = measured;
    o.sigma_m = 0.01;
    o.sigma_rad = 1.0 * M_PI / 180.0;
    w.graph.odometry.push_back(o);
  }
  for (int k = 1; k < 10; ++k) w.graph.poses[static_cast<std::size_t>(k)] = w.graph.poses[static_cast<std::size_t>(k - 1)] * w.graph.odometry[static_cast<std::size_t>(k - 1)].relative;
  return w;
}

// The camera's pitch (about its x, the girder's across) and heading (about the world's up)
// against the truth, degrees.
std::pair<double, double> pitch_and_heading_deg(const Eigen::Isometry3d& pose, const Eigen::Isometry3d& truth) {
  const Eigen::AngleAxisd d(pose.linear() * truth.linear().transpose());  // world frame
  const Eigen::Vector3d w = d.axis() * d.angle() * 180.0 / M_PI;
  return {w.y(), w.z()};
}

// An IMU's true gravity, good to 0.1 degrees, on every pose but the held first one.
void add_true_gravity(TiltedWalk& w) {
  for (int k = 1; k < 10; ++k) {
    PoseGravity g;
    g.pose = k;
    g.in_pose = w.truth[static_cast<std::size_t>(k)].linear().transpose() * -Eigen::Vector3d::UnitZ();
    g.sigma_rad = 0.1 * M_PI / 180.0;
    w.graph.gravities.push_back(g);
  }
}

TEST(PoseGraph, AnImusGravityHoldsTheTiltAndLeavesTheHeadingToTheOdometry) {
  TiltedWalk w = tilted_walk();
  const auto [pitch_given, heading_given] = pitch_and_heading_deg(w.graph.poses.back(), w.truth.back());
  add_true_gravity(w);
  const PoseGraphSolution s = solve_pose_graph(w.graph);
  ASSERT_TRUE(s.converged);
  const auto [pitch, heading] = pitch_and_heading_deg(s.poses.back(), w.truth.back());
  std::printf("last pose: pitch %.3f deg (given %.3f), heading %.3f deg (given %.3f)\n", pitch, pitch_given, heading,
              heading_given);
  EXPECT_GT(std::abs(pitch_given), 4.0);  // nine steps of 0.5 degrees
  EXPECT_LT(std::abs(pitch), 0.05);
  EXPECT_NEAR(heading, heading_given, 0.05);  // gravity says nothing of the heading
}

// A frame read while the robot was pushed sideways: its gravity 3 degrees off, beside a good
// one on the same pose. Least squares splits the difference (measured: 1.49 degrees off).
TEST(PoseGraph, AGravityReadWhileTheRobotWasPushedPullsThePoseByLittle) {
  TiltedWalk w = tilted_walk();
  add_true_gravity(w);
  PoseGravity pushed = w.graph.gravities[4];
  ASSERT_EQ(pushed.pose, 5);
  pushed.in_pose = w.truth[5].linear().transpose() *
                   (Eigen::AngleAxisd(3.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()) * -Eigen::Vector3d::UnitZ());
  w.graph.gravities.push_back(pushed);
  PoseGraphOptions o;
  o.max_iterations = 200;  // a residual in Huber's linear part converges slowly: 51 iterations here
  const PoseGraphSolution s = solve_pose_graph(w.graph, o);
  const Eigen::Vector3d down_as_solved = s.poses[5].linear() * w.truth[5].linear().transpose() * -Eigen::Vector3d::UnitZ();
  const double tilt_deg = std::acos(std::min(1.0, -down_as_solved.z())) * 180.0 / M_PI;  // the heading aside
  std::printf("pushed pose: %.3f deg off, %d iterations\n", tilt_deg, s.iterations);
  ASSERT_TRUE(s.converged);
  EXPECT_LT(tilt_deg, 0.25);  // the good reading's 2-sigma Huber reach, 0.2 degrees
}

}  // namespace
}  // namespace tunnelmap
