#include "tests/support/synthetic_scene.h"

#include <limits>
#include <random>

namespace tunnelmap::test {

SyntheticFrame render_planes(const std::vector<AnalyticPlane>& planes, const Eigen::Isometry3d& pose,
                             const Eigen::Vector3d& bmin, const Eigen::Vector3d& bmax,
                             double noise_m, unsigned seed, const Intrinsics& K) {
  SyntheticFrame out;
  out.frame = DepthFrame::blank_mm(K);
  DepthFrame& f = out.frame;
  f.pose = pose;
  f.source = "synthetic";
  out.plane_id.assign(f.depth.size(), -1);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Eigen::Vector3d c = pose.translation();
  const double slack = 1e-6;
  for (int v = 0; v < K.height; ++v) {
    for (int u = 0; u < K.width; ++u) {
      const Eigen::Vector3d ray_cam = K.ray(u, v);  // z = 1
      const Eigen::Vector3d d = pose.linear() * ray_cam;
      double best_t = std::numeric_limits<double>::infinity();
      int best = -1;
      for (std::size_t k = 0; k < planes.size(); ++k) {
        const double denom = planes[k].normal.dot(d);
        if (std::abs(denom) < 1e-12) continue;
        const double t = -(planes[k].normal.dot(c) + planes[k].offset) / denom;
        if (t <= 0 || t >= best_t) continue;
        const Eigen::Vector3d x = c + t * d;
        if ((x.array() < bmin.array() - slack).any() || (x.array() > bmax.array() + slack).any()) continue;
        best_t = t;
        best = static_cast<int>(k);
      }
      if (best < 0) continue;
      const std::size_t i = static_cast<std::size_t>(v) * K.width + u;
      double z = best_t;  // ray_cam has z = 1, so t is the depth
      if (noise_m > 0) z += noise_m * noise(rng);
      f.depth[i] = static_cast<float>(z * 1000.0);
      out.plane_id[i] = best;
    }
  }
  return out;
}

std::vector<AnalyticPlane> box_room(const Eigen::Vector3d& mn, const Eigen::Vector3d& mx) {
  std::vector<AnalyticPlane> p;
  for (int axis = 0; axis < 3; ++axis) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    n[axis] = 1.0;  // wall at min, facing +axis (inward)
    p.push_back({n, -mn[axis]});
    p.push_back({-n, mx[axis]});  // wall at max, facing -axis
  }
  return p;
}

Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                          const Eigen::Vector3d& up) {
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();  // image right
  const Eigen::Vector3d y = z.cross(x);                // image down
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear().col(0) = x;
  T.linear().col(1) = y;
  T.linear().col(2) = z;
  T.translation() = eye;
  return T;
}

}  // namespace tunnelmap::test
