#pragma once
// A pose graph with plane landmarks, solved by robust least squares (Ceres): camera poses linked
// by odometry factors, and planes (n . x = d, world frame) that the poses observe as patches of
// points. A patch enters by its moments (weight, centroid, spread), which gives exactly the sum
// of its points' squared distances to the plane at the cost of one residual block. Generic: it
// knows nothing of tunnels (core/mapping/structure_slam.h builds the graph of a girder).
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace tunnelmap {

struct GraphOdometry {
  int from = 0, to = 0;
  Eigen::Isometry3d relative = Eigen::Isometry3d::Identity();  // pose_from^-1 * pose_to, measured
  double sigma_m = 0.01, sigma_rad = 0.003;                   // its uncertainty per axis
  // Where the position error of the odometry lives: false, in the `from` pose's frame (a
  // heading error then carries the step sideways); true, in the world frame, apart from the
  // heading (position and heading drift as two random walks): `world_step` = to - from.
  bool world_translation = false;
  Eigen::Vector3d world_step = Eigen::Vector3d::Zero();
};

struct GraphPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  // unit
  double offset = 0.0;                                // n . x = offset (world)
};

// Points of one plane seen from one pose, in that pose's frame: their centroid and the square
// root of their scatter about it (scatter = spread * spread^T, per point, i.e. a covariance).
struct PlanePatch {
  int pose = 0, plane = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  double sigma_m = 0.002;  // uncertainty of the centroid's distance to the plane
};

// Two planes that are one surface (neighbouring stretches of one wall): at `point`, between
// them, they lie the same distance from it within `sigma_m`. Their directions may differ (a
// curving wall): half-way between two tangents of a smooth curve, both are off it alike. The
// point is held in the frame of `pose`, so that it moves with the map.
// With `sigma_rad` > 0 their normals also agree along `across` (a unit direction held in the
// pose's frame): for a side wall and the world's up, the wall may turn and climb but does not
// roll.
struct PlaneContinuity {
  int a = 0, b = 0;
  int pose = 0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // in the pose's frame
  double sigma_m = 0.002;                           // 0: distances free (directions alone tied)
  Eigen::Vector3d across = Eigen::Vector3d::Zero();  // in the pose's frame
  double sigma_rad = 0.0;                            // 0: directions free
};

// Stretches of one wall in order along it, each the mean of its planes' normals, combined with
// weights that sum to zero (a finite difference along the wall): the combination is zero within
// `sigma_rad` where the wall turns as the girder's alignment does
// (core/mapping/compartment_bends.h).
struct PlaneBend {
  std::vector<std::vector<int>> stretches;
  std::vector<double> weights;
  double sigma_rad = 0.001;
};

// A bend's departure from `means` (each stretch's mean normal, in the bend's order): their
// weighted sum, less its part along their mean direction. That part is second order in the
// turns between the stretches (1 - cos of the turn, for an even turn) and says nothing of how
// the wall turns; left in, it would pull a tightly turning wall straighter.
template <typename T>
Eigen::Matrix<T, 3, 1> bend_departure(const std::vector<Eigen::Matrix<T, 3, 1>>& means, const std::vector<double>& weights) {
  Eigen::Matrix<T, 3, 1> sum = Eigen::Matrix<T, 3, 1>::Zero(), direction = Eigen::Matrix<T, 3, 1>::Zero();
  for (std::size_t k = 0; k < means.size(); ++k) {
    sum += T(weights[k]) * means[k];
    direction += T(std::abs(weights[k])) * means[k];
  }
  direction /= direction.norm();
  return sum - sum.dot(direction) * direction;
}

// What an IMU at rest tells a pose: the direction things fall, in the pose's frame, is the
// world's `down` within `sigma_rad`. It fixes the pose's tilt (roll and pitch about the
// horizontal), not its heading.
struct PoseGravity {
  int pose = 0;
  Eigen::Vector3d in_pose = -Eigen::Vector3d::UnitZ();  // unit, the pose's frame
  Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();     // unit, the world frame
  double sigma_rad = 0.002;
};

struct PoseGraph {
  std::vector<Eigen::Isometry3d> poses;  // initial values
  std::vector<bool> fixed;               // per pose: held at its initial value
  std::vector<GraphOdometry> odometry;
  std::vector<GraphPlane> planes;        // initial values
  std::vector<PlanePatch> patches;
  std::vector<PlaneContinuity> continuities;
  std::vector<PlaneBend> bends;
  std::vector<PoseGravity> gravities;
};

struct PoseGraphOptions {
  double robust_sigmas = 2.0;  // patch, tie and gravity residuals beyond this many sigmas weigh less (Huber)
  int max_iterations = 50;
  int threads = 1;
};

struct PoseGraphSolution {
  std::vector<Eigen::Isometry3d> poses;
  std::vector<GraphPlane> planes;
  bool converged = false;
  int iterations = 0;
  // Costs of the whole graph; the part of the planes only one pose sees is taken at the
  // solved poses (core/solvers/pose_graph.cpp).
  double initial_cost = 0.0, final_cost = 0.0;
};

PoseGraphSolution solve_pose_graph(const PoseGraph& graph, const PoseGraphOptions& options = {});

// The information the patches of `pose` give about a small motion of it (rotation about
// `centre`, then translation; world frame, [rotation; translation]), at the solution's planes.
// Patches of planes no other pose sees are left out: such a plane follows the pose.
using PoseInformation = Eigen::Matrix<double, 6, 6>;
PoseInformation patch_information(const PoseGraph& graph, const PoseGraphSolution& solution, int pose,
                                  const Eigen::Vector3d& centre);
// The same for every pose at once (centres[i] for pose i), in one pass over the patches.
std::vector<PoseInformation> patch_information(const PoseGraph& graph, const PoseGraphSolution& solution,
                                               const std::vector<Eigen::Vector3d>& centres);

}  // namespace tunnelmap
