#include "core/planes/facing_cells.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace tunnelmap {

namespace {

// |cos| of the angle between a cell's own normal and its ray.
double facing(const CellFit& c) {
  const double r = c.mean.norm();
  return r > 0 ? std::abs(c.normal.dot(c.mean)) / r : 0.0;
}

// The noise bound (as CellFit::max_mse's, on RMS) at depth z for a surface at |cos| `facing`.
double bound_at(const CellGrid& g, double z, double facing) {
  return g.noise_multiple * z * z * std::max(g.noise_per_m2, g.axial_noise_per_m2 * facing);
}

// A cell that only the noise along the rays could make planar: it must at least pass the bound
// for a surface facing the camera squarely.
bool candidate(const CellFit& c, const CellGrid& g) {
  if (!c.fitted || c.planar) return false;
  const double b = bound_at(g, c.mean.z(), 1.0);
  return c.mse <= b * b;
}

struct Block {
  int members = 0;
  double count = 0, own = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double outer[6] = {0, 0, 0, 0, 0, 0};  // sum p p^T: xx xy xz yy yz zz
  const CellFit* cells[9];

  void add(const CellFit& c) {
    cells[members] = &c;
    ++members;
    count += c.count;
    own += c.mse * c.count;
    sum += c.sum_p;
    for (int k = 0; k < 6; ++k) outer[k] += c.sum_pp[k];
  }
};

// n^T S n for S given as xx xy xz yy yz zz.
double quadratic(const double s[6], const Eigen::Vector3d& n) {
  return n.x() * (n.x() * s[0] + 2 * n.y() * s[1] + 2 * n.z() * s[2]) + n.y() * (n.y() * s[3] + 2 * n.z() * s[4]) +
         n.z() * n.z() * s[5];
}

// The eigenvector of S's lowest eigenvalue. Less the noise S may be indefinite (the noise is an
// estimate), where the adjugate of smallest_eigenvector picks another; it serves the positive
// definite ones, most of them, at a fraction of a full solve's cost.
bool lowest_eigenvector(const double s[6], Eigen::Vector3d& v) {
  const double minor2 = s[0] * s[3] - s[1] * s[1];
  const double det = s[0] * (s[3] * s[5] - s[4] * s[4]) - s[1] * (s[1] * s[5] - s[4] * s[2]) +
                     s[2] * (s[1] * s[4] - s[3] * s[2]);
  if (s[0] > 0 && minor2 > 0 && det > 0) return smallest_eigenvector(s, v);
  Eigen::Matrix3d m;
  m << s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m);
  v = eig.eigenvectors().col(0);
  return v.squaredNorm() > 0.5;
}

// The middle eigenvalue of S given its smallest, l0 (as the block fits' standard error takes it).
double middle_eigenvalue(const double s[6], double l0) {
  const double t = s[0] + s[3] + s[5];
  const double minors = s[0] * s[3] - s[1] * s[1] + s[0] * s[5] - s[2] * s[2] + s[3] * s[5] - s[4] * s[4];
  const double sum12 = t - l0, prod12 = minors - l0 * sum12;
  return 0.5 * (sum12 - std::sqrt(std::max(0.0, sum12 * sum12 - 4 * prod12)));
}

// A block needs this many candidates to stand for a surface (as a region of noisy cells alone
// needs 4 cells, cell_growing.cpp).
constexpr int kMinMembers = 4;

// The block of cell (cu, cv): the candidates among it and its 8 neighbours. Planar cells stay
// out: at 3.3 m a block is 14 cm wide against 20-30 mm of noise, and with the planar cells
// around them the blocks grew small planes on a plate tilted 30-83 degrees off it, and one more
// edge-on strip along a manhole's rim (7; 6 before the admission, 4 with candidates alone).
Block block_of(const CellGrid& g, int cu, int cv, const std::vector<char>& is_candidate) {
  Block b;
  for (int v = std::max(0, cv - 1); v <= std::min(g.rows - 1, cv + 1); ++v)
    for (int u = std::max(0, cu - 1); u <= std::min(g.cols - 1, cu + 1); ++u) {
      const int i = g.index(u, v);
      if (is_candidate[i]) b.add(g.cells[i]);
    }
  return b;
}

// The block's plane fitted without the noise along the rays; false when the block does not
// pass smooth_cell_normals' tests with that noise at its facing. `normal` faces the camera.
bool fit_facing_block(const CellGrid& g, const Block& b, double max_f, Eigen::Vector3d& normal, double& se) {
  if (b.members < kMinMembers) return false;
  const Eigen::Vector3d mean = b.sum / b.count;
  const double z = mean.z();
  if (!(z > 0)) return false;
  const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  double scatter[6], without_noise[6];
  const Eigen::Vector3d q = mean / z;  // a point moved by dz along its ray moves by dz q
  const double sigma_z = g.axial_noise_per_m2 * z * z;
  for (int k = 0; k < 6; ++k) {
    scatter[k] = b.outer[k] - b.count * mean(ij[k][0]) * mean(ij[k][1]);
    without_noise[k] = scatter[k] - b.count * sigma_z * sigma_z * q(ij[k][0]) * q(ij[k][1]);
  }
  if (!lowest_eigenvector(without_noise, normal)) return false;
  if (normal.dot(mean) > 0) normal = -normal;
  const double cos = std::abs(normal.dot(mean)) / mean.norm();
  const double spread = std::max(0.0, quadratic(scatter, normal));
  double bound = 0.0;
  for (int k = 0; k < b.members; ++k) {
    const double r = bound_at(g, b.cells[k]->mean.z(), cos);
    bound += r * r * b.cells[k]->count;
  }
  const double sigma = z * z * std::max(g.noise_per_m2, g.axial_noise_per_m2 * cos);
  const double dof = std::max(1.0, b.count - 3 * b.members);
  const double noise = std::max(b.own / dof, sigma * sigma);
  if (spread > bound || (spread - b.own) / (3 * (b.members - 1)) > max_f * noise) return false;
  const double l1 = middle_eigenvalue(scatter, spread);
  se = l1 > 0 && b.count > 3 ? std::sqrt(spread / ((b.count - 3) * l1)) : M_PI;
  return true;
}

}  // namespace

double axial_noise_coefficient(const CellGrid& grid, std::vector<double>& ratios) {
  constexpr double kMinFacing = 0.3, kMaxNormalSe = 0.1, kMinRange = 1.0;
  ratios.clear();
  for (const CellFit& c : grid.cells) {
    const double f = facing(c);
    if (c.quiet && c.normal_se <= kMaxNormalSe && c.mean.z() >= kMinRange && f >= kMinFacing) {
      const double z2f = c.mean.z() * c.mean.z() * f;
      ratios.push_back(c.mse / (z2f * z2f));
    }
  }
  return root_of_lower_quartile(ratios);
}

void admit_cells_facing_the_camera(CellGrid& grid, double max_f) {
  if (!(grid.axial_noise_per_m2 > grid.noise_per_m2) || grid.noise_multiple <= 0) return;
  std::vector<char>& is_candidate = grid.candidates;
  is_candidate.assign(grid.cells.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i < grid.cells.size(); ++i) {
    is_candidate[i] = candidate(grid.cells[i], grid);
    any |= is_candidate[i] != 0;
  }
  if (!any) return;
  std::vector<CellAdmission>& admitted = grid.admissions;
  admitted.clear();
  for (int cv = 0; cv < grid.rows; ++cv)
    for (int cu = 0; cu < grid.cols; ++cu) {
      const int i = grid.index(cu, cv);
      if (!is_candidate[i]) continue;
      CellAdmission a;
      a.cell = i;
      if (!fit_facing_block(grid, block_of(grid, cu, cv, is_candidate), max_f, a.normal, a.se)) continue;
      const CellFit& c = grid.cells[i];
      const double bound = bound_at(grid, c.mean.z(), std::abs(a.normal.dot(c.mean)) / c.mean.norm());
      a.max_mse = bound * bound;
      if (c.mse <= a.max_mse) admitted.push_back(a);
    }
  for (const CellAdmission& a : admitted) {  // after all blocks are fitted: none sees another's admission
    CellFit& c = grid.cells[a.cell];
    c.max_mse = a.max_mse;
    c.planar = c.block_fitted = true;
    c.block_normal = a.normal;
    c.block_se = c.normal_se = a.se;
  }
}

}  // namespace tunnelmap
