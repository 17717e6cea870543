#include "core/fusion/mesh_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tunnelmap {

MeshAccuracy mesh_accuracy(const TriangleMesh& mesh, const std::vector<PlaneRef>& planes,
                           double tolerance_m) {
  MeshAccuracy a;
  a.vertices = mesh.vertices.size();
  if (a.vertices == 0 || planes.empty()) return a;
  std::vector<double> d;
  d.reserve(a.vertices);
  std::size_t in = 0;
  double sq = 0.0;
  for (const Eigen::Vector3f& v : mesh.vertices) {
    double best = std::numeric_limits<double>::infinity();
    for (const PlaneRef& p : planes)
      best = std::min(best, std::abs(p.normal.dot(v.cast<double>()) + p.offset));
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
