// Own RANSAC (Fischler & Bolles) rather than pcl::SACSegmentation: PCL's sampler is seeded with
// a constant, so 100 repetitions would all return the same planes; here every repetition has
// its own std::mt19937 stream derived from the seed, which keeps the runs reproducible.
#include "core/baselines/ransac_lse.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "core/util/error.h"

namespace tunnelmap {

namespace {

struct Plane {
  Eigen::Vector3f n = Eigen::Vector3f::UnitZ();
  float d = 0.f;  // n.x + d = 0
};

struct Extracted {
  Plane plane;
  std::vector<int> members;  // indices into the sampled point list
};

// Least-squares plane of the given points: centroid and smallest principal axis.
Plane fit_lse(const std::vector<Eigen::Vector3f>& pts, const std::vector<int>& idx) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i : idx) c += pts[i].cast<double>();
  c /= static_cast<double>(idx.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : idx) {
    const Eigen::Vector3d q = pts[i].cast<double>() - c;
    cov += q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  const Eigen::Vector3d n = es.eigenvectors().col(0).normalized();
  Plane p;
  p.n = n.cast<float>();
  p.d = static_cast<float>(-n.dot(c));
  return p;
}

// One RANSAC plane among `remaining`; returns inliers of the LSE-refined plane.
Extracted extract_one(const std::vector<Eigen::Vector3f>& pts, const std::vector<int>& remaining,
                      const RansacLseOptions& o, std::mt19937& rng) {
  Extracted best;
  const int m = static_cast<int>(remaining.size());
  if (m < 3) return best;
  std::uniform_int_distribution<int> pick(0, m - 1);
  const float eps = static_cast<float>(o.distance_m);
  int best_count = 0;
  Plane best_plane;
  double needed = o.max_trials;
  for (int trial = 0; trial < o.max_trials && trial < needed; ++trial) {
    const Eigen::Vector3f& a = pts[remaining[pick(rng)]];
    const Eigen::Vector3f& b = pts[remaining[pick(rng)]];
    const Eigen::Vector3f& c = pts[remaining[pick(rng)]];
    Eigen::Vector3f n = (b - a).cross(c - a);
    const float len = n.norm();
    if (!(len > 1e-6f)) continue;
    n /= len;
    const float d = -n.dot(a);
    int count = 0;
    for (int i : remaining) count += std::abs(n.dot(pts[i]) + d) < eps;
    if (count > best_count) {
      best_count = count;
      best_plane = {n, d};
      const double w = static_cast<double>(count) / m;
      const double p_all = std::max(1e-12, w * w * w);
      needed = p_all >= 1.0 ? 1.0 : std::log(1.0 - o.confidence) / std::log(1.0 - p_all);
    }
  }
  if (best_count < 3) return best;
  // Least-squares refinement: refit on the inliers, re-select, refit once more.
  Plane plane = best_plane;
  std::vector<int> members;
  for (int pass = 0; pass < 2; ++pass) {
    members.clear();
    for (int i : remaining)
      if (std::abs(plane.n.dot(pts[i]) + plane.d) < eps) members.push_back(i);
    if (members.size() < 3) break;
    plane = fit_lse(pts, members);
  }
  members.clear();
  for (int i : remaining)
    if (std::abs(plane.n.dot(pts[i]) + plane.d) < eps) members.push_back(i);
  best.plane = plane;
  best.members = std::move(members);
  return best;
}

// One full sequential segmentation; returns its truncated squared error (unexplained points
// cost eps^2 each, so taking fewer points never looks better).
double segment_once(const std::vector<Eigen::Vector3f>& pts, const RansacLseOptions& o,
                    std::mt19937& rng, std::vector<Extracted>& planes) {
  planes.clear();
  std::vector<int> remaining(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) remaining[i] = static_cast<int>(i);
  const double eps2 = o.distance_m * o.distance_m;
  double sse = 0.0;
  std::vector<char> taken(pts.size(), 0);
  while (static_cast<int>(planes.size()) < o.max_planes) {
    Extracted e = extract_one(pts, remaining, o, rng);
    if (static_cast<int>(e.members.size()) < o.min_plane_points) break;
    for (int i : e.members) {
      const double r = e.plane.n.dot(pts[i]) + e.plane.d;
      sse += r * r;
      taken[i] = 1;
    }
    std::vector<int> rest;
    rest.reserve(remaining.size() - e.members.size());
    for (int i : remaining)
      if (!taken[i]) rest.push_back(i);
    remaining.swap(rest);
    planes.push_back(std::move(e));
  }
  sse += eps2 * static_cast<double>(remaining.size());
  return sse;
}

}  // namespace

RansacLseResult ransac_lse_planes(const OrganizedCloud& cloud, const RansacLseOptions& o) {
  if (o.iterations < 1 || o.sample_step < 1 || !(o.distance_m > 0) || o.max_planes < 1 ||
      o.min_plane_points < 3 || o.max_trials < 1 || !(o.confidence > 0 && o.confidence < 1))
    throw ParameterError("R&L options out of range (iterations, step, planes >= 1; distance > 0)");
  RansacLseResult out;
  out.planes.width = cloud.width;
  out.planes.height = cloud.height;
  out.planes.labels.assign(static_cast<size_t>(cloud.width) * cloud.height, 0);
  const auto start = std::chrono::steady_clock::now();

  std::vector<Eigen::Vector3f> pts;
  std::vector<size_t> pixel;
  for (int v = 0; v < cloud.height; v += o.sample_step)
    for (int u = 0; u < cloud.width; u += o.sample_step) {
      const Eigen::Vector3f& p = cloud.points[cloud.index(u, v)];
      if (!OrganizedCloud::valid(p)) continue;
      pts.push_back(p);
      pixel.push_back(cloud.index(u, v));
    }

  std::vector<Extracted> best, current;
  double best_sse = std::numeric_limits<double>::infinity();
  for (int it = 0; it < o.iterations; ++it) {
    std::mt19937 rng(o.seed * 1000003u + static_cast<std::uint32_t>(it));
    const double sse = segment_once(pts, o, rng, current);
    if (sse < best_sse) {
      best_sse = sse;
      best.swap(current);
      out.winning_iteration = it;
    }
  }
  out.squared_error = std::isfinite(best_sse) ? best_sse : 0.0;

  const double step2 = static_cast<double>(o.sample_step) * o.sample_step;
  const Intrinsics& K = cloud.intrinsics;
  for (size_t k = 0; k < best.size(); ++k) {
    const Extracted& e = best[k];
    PlaneSegment s;
    s.id = static_cast<int>(k) + 1;
    Eigen::Vector3d n = e.plane.n.cast<double>().normalized();
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i : e.members) c += pts[i].cast<double>();
    c /= static_cast<double>(e.members.size());
    if (n.dot(c) > 0) n = -n;  // face the camera like PG&C's planes
    const double d = -n.dot(c);  // the LSE plane passes through the inliers' centroid
    s.normal = n;
    s.mean_normal = n;
    s.centroid = c;
    s.offset_m = d;
    s.points = static_cast<int>(e.members.size() * step2);
    double sq = 0.0, area = 0.0;
    s.bbox_u0 = cloud.width;
    s.bbox_v0 = cloud.height;
    for (int i : e.members) {
      const Eigen::Vector3d p = pts[i].cast<double>();
      const double r = n.dot(p) + d;
      sq += r * r;
      const double z = p.z();
      const double cos_incidence = std::max(0.1, std::abs(n.dot(p.normalized())));
      area += step2 * z * z / (K.fx * K.fy) / cos_incidence;
      const int u = static_cast<int>(pixel[i] % cloud.width);
      const int v = static_cast<int>(pixel[i] / cloud.width);
      s.bbox_u0 = std::min(s.bbox_u0, u);
      s.bbox_v0 = std::min(s.bbox_v0, v);
      s.bbox_u1 = std::max(s.bbox_u1, u);
      s.bbox_v1 = std::max(s.bbox_v1, v);
      out.planes.labels[pixel[i]] = s.id;
    }
    s.rms_m = std::sqrt(sq / e.members.size());
    s.area_m2 = area;
    out.planes.planes.push_back(std::move(s));
  }
  out.planes.timings_ms["planes"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tunnelmap
