#include "core/planes/plane_growing.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/planes/plane_contour.h"
#include "core/planes/plane_model.h"

namespace tunnelmap {

namespace {

constexpr std::int32_t kNoNormal = -1;  // pixel can never join a plane
constexpr std::int32_t kFree = 0;

// Calls visit(j) for every free pixel j in the (2H+1)^2 window around interior pixel i.
template <int H, typename Visit>
inline void scan_window(const std::int32_t* labels, int i, int w, Visit&& visit) {
#pragma GCC unroll 8
  for (int dv = -H; dv <= H; ++dv) {
    const int row = i + dv * w;
#pragma GCC unroll 8
    for (int du = -H; du <= H; ++du) {
      if (du == 0 && dv == 0) continue;
      if (labels[row + du] == kFree) visit(row + du);
    }
  }
}

// Working state of one extraction: a flat label image, index queues, no per-point containers.
class Grower {
 public:
  Grower(const OrganizedCloud& c, const GrowOptions& o, std::vector<std::int32_t>& labels)
      : cloud_(c), labels_(labels), w_(c.width), h_(c.height) {
    tried_.assign(labels.size(), 0);
    cos_angle_ = static_cast<float>(std::cos(o.angle_deg * M_PI / 180.0));
    eps_ = static_cast<float>(o.distance_m);
    cand2_ = static_cast<float>(o.candidate_distance_m * o.candidate_distance_m);
    half_ = o.neighbourhood_n / 2;
    for (int dv = -half_; dv <= half_; ++dv)
      for (int du = -half_; du <= half_; ++du)
        if (du != 0 || dv != 0) {
          offsets_.push_back(dv * w_ + du);
          steps_.push_back({du, dv});
        }
    for (std::size_t i = 0; i < labels.size(); ++i)
      labels[i] = c.normals[i].x() == c.normals[i].x() ? kFree : kNoNormal;
  }

  bool seedable(int i) const { return labels_[i] == kFree && !tried_[i]; }

  // Seed: a 2x2 block of free pixels whose normals agree within lambda and whose points lie
  // within epsilon of the plane through their mean (the paper's "three or four adjacent points").
  bool seed(int u, int v, PlaneModel& model) const {
    if (u + 1 >= w_ || v + 1 >= h_) return false;
    const int idx[4] = {v * w_ + u, v * w_ + u + 1, (v + 1) * w_ + u, (v + 1) * w_ + u + 1};
    for (int i : idx)
      if (!seedable(i)) return false;
    const Eigen::Vector3f& n0 = cloud_.normals[idx[0]];
    for (int k = 1; k < 4; ++k)
      if (cloud_.normals[idx[k]].dot(n0) < cos_angle_) return false;
    for (int i : idx) model.add(cloud_.points[i], cloud_.normals[i]);
    Eigen::Vector3f p, n;
    model.growth_model(p, n);
    for (int i : idx)
      if (std::abs(n.dot(cloud_.points[i] - p)) > eps_) return false;
    return true;
  }

  // Breadth-first growth from the seed block with the eq. 2 tests and eq. 4 updates.
  // `members()` then lists the region's pixels.
  void grow(int u, int v, int id, PlaneModel& model) {
    members_.clear();
    const int seeds[4] = {v * w_ + u, v * w_ + u + 1, (v + 1) * w_ + u, (v + 1) * w_ + u + 1};
    for (int i : seeds) {
      labels_[i] = id;
      members_.push_back(i);
    }
    Eigen::Vector3f mp, mn;
    model.growth_model(mp, mn);
    float d0 = mn.dot(mp);  // plane: mn.x - d0 = 0
    // Raw pointers in the hot loop: the compiler cannot otherwise keep them in registers
    // across the label writes.
    std::int32_t* const labels = labels_.data();
    const Eigen::Vector3f* const points = cloud_.points.data();
    const Eigen::Vector3f* const normals = cloud_.normals.data();
    const int* const offsets = offsets_.data();
    const int n_off = static_cast<int>(offsets_.size());
    const float eps = eps_, cand2 = cand2_, cos_angle = cos_angle_;
    // Candidate test (eq. 2 plus the candidate distance) and model update (eq. 4).
    auto try_join = [&](int j, const Eigen::Vector3f& pi) {
      const Eigen::Vector3f q = points[j];
      if ((q - pi).squaredNorm() > cand2) return;  // candidate distance
      if (std::abs(mn.dot(q) - d0) > eps) return;   // point-to-plane, eq. 2
      const Eigen::Vector3f nq = normals[j];
      if (nq.dot(mn) < cos_angle) return;            // normal angle, eq. 2
      labels[j] = id;
      model.add(q, nq);                              // eq. 4
      model.growth_model(mp, mn);
      d0 = mn.dot(mp);
      members_.push_back(j);
    };
    for (std::size_t head = 0; head < members_.size(); ++head) {
      const int i = members_[head];
      const int cu = i % w_, cv = i / w_;
      const Eigen::Vector3f pi = points[i];
      const bool interior = cu >= half_ && cv >= half_ && cu < w_ - half_ && cv < h_ - half_;
      if (interior) {
        // Hot path: the n*n window fully unrolled for the usual n.
        switch (half_) {
          case 1: scan_window<1>(labels, i, w_, [&](int j) { try_join(j, pi); }); continue;
          case 2: scan_window<2>(labels, i, w_, [&](int j) { try_join(j, pi); }); continue;
          case 3: scan_window<3>(labels, i, w_, [&](int j) { try_join(j, pi); }); continue;
          default: break;
        }
      }
      for (int k = 0; k < n_off; ++k) {
        const int nu = cu + steps_[k].first, nv = cv + steps_[k].second;
        if (nu < 0 || nv < 0 || nu >= w_ || nv >= h_) continue;
        const int j = i + offsets[k];
        if (labels[j] == kFree) try_join(j, pi);
      }
    }
  }

  const std::vector<int>& members() const { return members_; }

  // A rejected region's pixels become free again but never seed again.
  void release(int id) {
    for (int m : members_) {
      labels_[m] = kFree;
      tried_[m] = 1;
    }
    (void)id;
  }

 private:
  const OrganizedCloud& cloud_;
  std::vector<std::int32_t>& labels_;
  int w_, h_;
  std::vector<std::uint8_t> tried_;
  std::vector<int> members_;  // doubles as the BFS queue
  std::vector<int> offsets_;                // neighbour index steps (n*n - 1)
  std::vector<std::pair<int, int>> steps_;  // the same steps as (du, dv), for border pixels
  float cos_angle_, eps_, cand2_;
  int half_;
};

}  // namespace

PlaneSegments extract_planes(const OrganizedCloud& cloud, const GrowOptions& options) {
  PlaneSegments out;
  StageTimer timer(out.timings_ms, "planes");
  out.width = cloud.width;
  out.height = cloud.height;
  out.labels.assign(static_cast<std::size_t>(cloud.width) * cloud.height, 0);
  if (cloud.normals.size() != out.labels.size() || cloud.points.size() != out.labels.size()) return out;

  Grower grower(cloud, options, out.labels);
  const double fxfy = cloud.intrinsics.fx * cloud.intrinsics.fy;
  const int w = cloud.width;
  int next_id = 1;
  for (int v = 0; v < cloud.height; ++v) {
    for (int u = 0; u < w; ++u) {
      if (!grower.seedable(v * w + u)) continue;
      PlaneModel model;
      if (!grower.seed(u, v, model)) continue;
      grower.grow(u, v, next_id, model);  // `model` already holds the seed block

      PlaneSegment plane;
      plane.id = next_id;
      plane.points = static_cast<int>(model.count());
      plane.centroid = model.mean_point();
      plane.mean_normal = model.mean_normal().normalized();
      double rms = 0;
      const Eigen::Vector3d lsq = model.least_squares_normal(&rms);
      plane.rms_m = rms;
      plane.normal = options.refit_normal ? lsq : plane.mean_normal;
      plane.offset_m = -plane.normal.dot(plane.centroid);
      // Pixel footprint on the plane: z^3 / (fx fy |n.p|), and n.p = -offset on the plane.
      plane.area_m2 = std::abs(plane.offset_m) > 1e-9 ? model.sum_z_cubed() / (fxfy * std::abs(plane.offset_m)) : 0.0;
      if (plane.points < options.min_points || plane.area_m2 < options.min_area_m2) {
        grower.release(next_id);
        continue;
      }
      int u0 = w, v0 = cloud.height, u1 = -1, v1 = -1;
      for (int m : grower.members()) {
        const int mu = m % w, mv = m / w;
        u0 = std::min(u0, mu), u1 = std::max(u1, mu);
        v0 = std::min(v0, mv), v1 = std::max(v1, mv);
      }
      plane.bbox_u0 = u0, plane.bbox_v0 = v0, plane.bbox_u1 = u1, plane.bbox_v1 = v1;
      out.planes.push_back(std::move(plane));
      ++next_id;
    }
  }
  for (auto& l : out.labels)
    if (l < 0) l = 0;  // pixels without normals: no plane
  if (options.compute_contours) {
    StageTimer contour_timer(out.timings_ms, "contours");
    for (PlaneSegment& plane : out.planes) compute_contour(out.labels, w, cloud.intrinsics, plane);
  }
  return out;
}

}  // namespace tunnelmap
