#include "core/fusion/mesh_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace tunnelmap {

MeshAccuracy mesh_accuracy(const TriangleMesh& mesh, const std::vector<PlaneRef>& planes,
                           double tolerance_m, const Eigen::Isometry3d& mesh_to_planes) {
  MeshAccuracy a;
  a.vertices = mesh.vertices.size();
  if (a.vertices == 0 || planes.empty()) return a;
  std::vector<double> d;
  d.reserve(a.vertices);
  std::size_t in = 0;
  double sq = 0.0;
  for (const Eigen::Vector3f& vertex : mesh.vertices) {
    const Eigen::Vector3d v = mesh_to_planes * vertex.cast<double>();
    double best = std::numeric_limits<double>::infinity();
    for (const PlaneRef& p : planes) best = std::min(best, std::abs(p.normal.dot(v) + p.offset));
    d.push_back(best);
    sq += best * best;
    if (best <= tolerance_m) ++in;
  }
  std::sort(d.begin(), d.end());
  a.fraction_within = double(in) / double(a.vertices);
  a.median_m = d[d.size() / 2];
  a.p95_m = d[std::min(d.size() - 1, static_cast<std::size_t>(0.95 * double(d.size())))];
  a.rms_m = std::sqrt(sq / double(a.vertices));
  return a;
}

Eigen::Isometry3d align_mesh_to_planes(const TriangleMesh& mesh, const std::vector<PlaneRef>& planes,
                                       double max_distance_m, int iterations) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  if (mesh.vertices.empty() || planes.empty()) return T;
  // Every 4th vertex is plenty for six unknowns and keeps this fast on large meshes.
  const std::size_t stride = std::max<std::size_t>(1, mesh.vertices.size() / 200000 + 1);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for (std::size_t i = 0; i < mesh.vertices.size(); i += stride, ++count)
    centre += mesh.vertices[i].cast<double>();
  centre /= double(count);
  for (int it = 0; it < iterations; ++it) {
    Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t i = 0; i < mesh.vertices.size(); i += stride) {
      const Eigen::Vector3d x = T * mesh.vertices[i].cast<double>();
      const PlaneRef* best = nullptr;
      double best_d = max_distance_m;
      for (const PlaneRef& p : planes) {
        const double d = std::abs(p.normal.dot(x) + p.offset);
        if (d < best_d) best_d = d, best = &p;
      }
      if (!best) continue;
      const double r = best->normal.dot(x) + best->offset;
      Eigen::Matrix<double, 6, 1> J;
      J.head<3>() = (x - centre).cross(best->normal);
      J.tail<3>() = best->normal;
      H += J * J.transpose();
      b -= J * r;
    }
    // Directions no plane constrains (e.g. along a straight tunnel) stay where they are.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(H);
    const double top = eig.eigenvalues().maxCoeff();
    if (!(top > 0)) break;
    Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
    for (int k = 0; k < 6; ++k)
      if (eig.eigenvalues()[k] > 1e-6 * top)
        d += eig.eigenvectors().col(k) * (eig.eigenvectors().col(k).dot(b) / eig.eigenvalues()[k]);
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    const double angle = d.head<3>().norm();
    if (angle > 0) step.linear() = Eigen::AngleAxisd(angle, d.head<3>() / angle).toRotationMatrix();
    step.translation() = centre - step.linear() * centre + d.tail<3>();
    T = step * T;
    if (angle < 1e-7 && d.tail<3>().norm() < 1e-7) break;
  }
  return T;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Eigen::Isometry3d& T) {
  TriangleMesh out = mesh;
  for (Eigen::Vector3f& v : out.vertices) v = (T * v.cast<double>()).cast<float>();
  for (Eigen::Vector3f& n : out.normals) n = (T.linear() * n.cast<double>()).cast<float>();
  return out;
}

std::vector<PlaneRef> ground_truth_planes(const nlohmann::json& gt) {
  std::vector<PlaneRef> out;
  if (!gt.is_object() || !gt.contains("surfaces") || !gt["surfaces"].is_array()) return out;
  for (const nlohmann::json& s : gt["surfaces"]) {
    if (!s.is_object() || !s.contains("normal") || !s.contains("offset_m")) continue;
    const nlohmann::json& n = s["normal"];
    if (!n.is_array() || n.size() != 3 || !s["offset_m"].is_number()) continue;
    PlaneRef p;
    p.normal = Eigen::Vector3d(n[0].get<double>(), n[1].get<double>(), n[2].get<double>());
    if (p.normal.norm() < 1e-9) continue;
    p.offset = s["offset_m"].get<double>() / p.normal.norm();
    p.normal.normalize();
    out.push_back(p);
  }
  return out;
}

}  // namespace tunnelmap
