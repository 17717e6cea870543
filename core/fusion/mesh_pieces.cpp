#include "core/fusion/mesh_pieces.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap {

namespace {

// Copies triangle `t` of `from` into `to`, its vertices once each (`remap`: -1 = not yet).
void copy_triangle(const TriangleMesh& from, const std::array<std::int32_t, 3>& t,
                   std::vector<std::int32_t>& remap, TriangleMesh& to) {
  std::array<std::int32_t, 3> out;
  for (int k = 0; k < 3; ++k) {
    const std::size_t v = static_cast<std::size_t>(t[std::size_t(k)]);
    if (remap[v] < 0) {
      remap[v] = static_cast<std::int32_t>(to.vertices.size());
      to.vertices.push_back(from.vertices[v]);
      if (!from.normals.empty()) to.normals.push_back(from.normals[v]);
      if (!from.colors.empty()) to.colors.push_back(from.colors[v]);
    }
    out[std::size_t(k)] = remap[v];
  }
  to.triangles.push_back(out);
}

}  // namespace

std::vector<MeshPiece> split_mesh(const TriangleMesh& mesh, const StationAxis& axis, std::vector<double> cuts) {
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  std::vector<MeshPiece> pieces(cuts.size() + 1);
  std::vector<std::vector<std::int32_t>> remaps(pieces.size());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f c = (mesh.vertices[std::size_t(t[0])] + mesh.vertices[std::size_t(t[1])] +
                               mesh.vertices[std::size_t(t[2])]) / 3.0f;
    const std::size_t p =
        static_cast<std::size_t>(std::upper_bound(cuts.begin(), cuts.end(), axis.station(c)) - cuts.begin());
    if (remaps[p].empty()) remaps[p].assign(mesh.vertices.size(), -1);
    copy_triangle(mesh, t, remaps[p], pieces[p].mesh);
  }
  std::vector<MeshPiece> out;
  for (MeshPiece& piece : pieces) {
    if (piece.mesh.triangles.empty()) continue;
    piece.from_m = std::numeric_limits<double>::infinity();
    piece.to_m = -piece.from_m;
    for (const Eigen::Vector3f& v : piece.mesh.vertices) {
      piece.from_m = std::min(piece.from_m, axis.station(v));
      piece.to_m = std::max(piece.to_m, axis.station(v));
      piece.bounds.extend(v.cast<double>());
    }
    out.push_back(std::move(piece));
  }
  return out;
}

std::vector<double> regular_cuts(const TriangleMesh& mesh, const StationAxis& axis, double length_m) {
  if (mesh.vertices.empty() || !(length_m > 0)) return {};
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Eigen::Vector3f& v : mesh.vertices) {
    lo = std::min(lo, axis.station(v));
    hi = std::max(hi, axis.station(v));
  }
  std::vector<double> cuts;
  for (double s = lo + length_m; s < hi; s += length_m) cuts.push_back(s);
  return cuts;
}

StationAxis principal_axis(const TriangleMesh& mesh) {
  StationAxis a;
  if (mesh.vertices.size() < 2) return a;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3f& v : mesh.vertices) mean += v.cast<double>();
  mean /= double(mesh.vertices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3f& v : mesh.vertices) {
    const Eigen::Vector3d d = v.cast<double>() - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  a.point = mean;
  a.direction = es.eigenvectors().col(2).normalized();  // largest eigenvalue
  if (a.direction.maxCoeff() < -a.direction.minCoeff()) a.direction = -a.direction;  // a stable sign
  return a;
}

}  // namespace tunnelmap
