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

namespace {

// Each triangle's piece: the number of cuts below its centroid's station.
std::vector<std::uint32_t> piece_of_triangles(const TriangleMesh& mesh, const StationAxis& axis,
                                              const std::vector<double>& cuts) {
  std::vector<std::uint32_t> piece_of(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const Eigen::Vector3f c = (mesh.vertices[std::size_t(t[0])] + mesh.vertices[std::size_t(t[1])] +
                               mesh.vertices[std::size_t(t[2])]) / 3.0f;
    piece_of[i] =
        static_cast<std::uint32_t>(std::upper_bound(cuts.begin(), cuts.end(), axis.station(c)) - cuts.begin());
  }
  return piece_of;
}

// The triangles grouped by piece, in mesh order within each (a counting sort): piece p's are
// by_piece[first[p]] .. by_piece[first[p + 1] - 1].
void group_by_piece(const std::vector<std::uint32_t>& piece_of, std::size_t pieces, std::vector<std::size_t>& first,
                    std::vector<std::uint32_t>& by_piece) {
  first.assign(pieces + 1, 0);
  for (std::uint32_t p : piece_of) ++first[p + 1];
  for (std::size_t p = 1; p < first.size(); ++p) first[p] += first[p - 1];
  by_piece.resize(piece_of.size());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < piece_of.size(); ++i) by_piece[next[piece_of[i]]++] = static_cast<std::uint32_t>(i);
}

}  // namespace

std::vector<MeshPiece> split_mesh(const TriangleMesh& mesh, const StationAxis& axis, std::vector<double> cuts) {
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  // The pieces one after the other through one vertex map (a map per piece would hold 4 bytes
  // per vertex of the whole mesh for every piece: 700 MB for a 100 m girder in 25 pieces).
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> by_piece;
  group_by_piece(piece_of_triangles(mesh, axis, cuts), cuts.size() + 1, first, by_piece);
  std::vector<std::int32_t> remap(mesh.vertices.size(), -1);
  std::vector<MeshPiece> out;
  for (std::size_t p = 0; p + 1 < first.size(); ++p) {
    if (first[p] == first[p + 1]) continue;
    MeshPiece piece;
    for (std::size_t k = first[p]; k < first[p + 1]; ++k) copy_triangle(mesh, mesh.triangles[by_piece[k]], remap, piece.mesh);
    for (std::size_t k = first[p]; k < first[p + 1]; ++k)  // back to "not yet" for the next piece
      for (std::int32_t v : mesh.triangles[by_piece[k]]) remap[std::size_t(v)] = -1;
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
