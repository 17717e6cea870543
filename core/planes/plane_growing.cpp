#include "core/planes/plane_growing.h"

#include <cmath>
#include <vector>

#include "core/planes/plane_contour.h"
#include "core/planes/plane_model.h"

namespace tunnelmap {

namespace {

bool has_normal(const Eigen::Vector3f& n) { return n.x() == n.x(); }

// Working state of one extraction: flat arrays, no per-point containers.
struct Grower {
  const OrganizedCloud& cloud;
  const GrowOptions& opt;
  std::vector<std::int32_t>& labels;
  std::vector<std::uint8_t> tried;  // pixels of rejected regions: never seeds again
  std::vector<int> queue;
  std::vector<int> members;
  float cos_angle, eps, cand2;
  int half;

  Grower(const OrganizedCloud& c, const GrowOptions& o, std::vector<std::int32_t>& l)
      : cloud(c), opt(o), labels(l) {
    tried.assign(labels.size(), 0);
    cos_angle = static_cast<float>(std::cos(o.angle_deg * M_PI / 180.0));
    eps = static_cast<float>(o.distance_m);
    cand2 = static_cast<float>(o.candidate_distance_m * o.candidate_distance_m);
    half = o.neighbourhood_n / 2;
  }

  bool free_pixel(int i) const { return labels[i] == 0 && has_normal(cloud.normals[i]); }

  // Seed: a 2x2 block of free pixels whose normals agree within lambda and whose points lie
  // within epsilon of the plane through their mean (the paper's "three or four adjacent points").
  bool seed(int u, int v, PlaneModel& model) const {
    if (u + 1 >= cloud.width || v + 1 >= cloud.height) return false;
    const int w = cloud.width;
    const int idx[4] = {v * w + u, v * w + u + 1, (v + 1) * w + u, (v + 1) * w + u + 1};
    for (int i : idx)
      if (!free_pixel(i) || tried[i]) return false;
    const Eigen::Vector3f& n0 = cloud.normals[idx[0]];
    for (int k = 1; k < 4; ++k)
      if (cloud.normals[idx[k]].dot(n0) < cos_angle) return false;
    for (int i : idx) model.add(cloud.points[i], cloud.normals[i]);
    Eigen::Vector3f p, n;
    model.growth_model(p, n);
    for (int i : idx)
      if (std::abs(n.dot(cloud.points[i] - p)) > eps) return false;
    return true;
  }

  // Region growing from the seed (eq. 2 tests, eq. 4 updates). Returns the grown model;
  // `members` holds the region's pixels.
  void grow(int u, int v, int id, PlaneModel& model) {
    const int w = cloud.width, h = cloud.height;
    members.clear();
    queue.clear();
    const int seeds[4] = {v * w + u, v * w + u + 1, (v + 1) * w + u, (v + 1) * w + u + 1};
    for (int i : seeds) {
      labels[i] = id;
      members.push_back(i);
      queue.push_back(i);
    }
    Eigen::Vector3f mp, mn;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      const int cu = i % w, cv = i / w;
      const Eigen::Vector3f& pi = cloud.points[i];
      const int ua = std::max(0, cu - half), ub = std::min(w - 1, cu + half);
      const int va = std::max(0, cv - half), vb = std::min(h - 1, cv + half);
      for (int nv = va; nv <= vb; ++nv) {
        for (int nu = ua; nu <= ub; ++nu) {
          const int j = nv * w + nu;
          if (!free_pixel(j)) continue;
          const Eigen::Vector3f& q = cloud.points[j];
          if ((q - pi).squaredNorm() > cand2) continue;
          model.growth_model(mp, mn);
          if (std::abs(mn.dot(q - mp)) > eps) continue;
          if (cloud.normals[j].dot(mn) < cos_angle) continue;
          labels[j] = id;
          model.add(q, cloud.normals[j]);
          members.push_back(j);
          queue.push_back(j);
        }
      }
    }
  }
};

}  // namespace

PlaneSegments extract_planes(const OrganizedCloud& cloud, const GrowOptions& options) {
  PlaneSegments out;
  StageTimer timer(out.timings_ms, "planes");
  out.width = cloud.width;
  out.height = cloud.height;
  out.labels.assign(static_cast<std::size_t>(cloud.width) * cloud.height, 0);
  if (cloud.normals.size() != out.labels.size()) return out;

  Grower grower(cloud, options, out.labels);
  const double fxfy = cloud.intrinsics.fx * cloud.intrinsics.fy;
  const int w = cloud.width;
  int next_id = 1;
  for (int v = 0; v < cloud.height; ++v) {
    for (int u = 0; u < w; ++u) {
      const int i = v * w + u;
      if (!grower.free_pixel(i) || grower.tried[i]) continue;
      PlaneModel model;
      if (!grower.seed(u, v, model)) continue;
      grower.grow(u, v, next_id, model);  // `model` already holds the seed block
      const PlaneModel& region = model;

      PlaneSegment plane;
      plane.id = next_id;
      plane.points = static_cast<int>(region.count());
      plane.centroid = region.mean_point();
      plane.mean_normal = region.mean_normal().normalized();
      plane.normal = options.refit_normal ? region.least_squares_normal(&plane.rms_m)
                                          : plane.mean_normal;
      if (!options.refit_normal) region.least_squares_normal(&plane.rms_m);
      plane.offset_m = -plane.normal.dot(plane.centroid);
      // Pixel footprint on the plane: z^3 / (fx fy |n.p|), and n.p = -offset on the plane.
      plane.area_m2 = std::abs(plane.offset_m) > 1e-9
                          ? region.sum_z_cubed() / (fxfy * std::abs(plane.offset_m))
                          : 0.0;
      const bool keep = plane.points >= options.min_points && plane.area_m2 >= options.min_area_m2;
      if (!keep) {
        for (int m : grower.members) {
          out.labels[m] = 0;
          grower.tried[m] = 1;
        }
        continue;
      }
      int u0 = w, v0 = cloud.height, u1 = -1, v1 = -1;
      for (int m : grower.members) {
        const int mu = m % w, mv = m / w;
        u0 = std::min(u0, mu), u1 = std::max(u1, mu);
        v0 = std::min(v0, mv), v1 = std::max(v1, mv);
      }
      plane.bbox_u0 = u0, plane.bbox_v0 = v0, plane.bbox_u1 = u1, plane.bbox_v1 = v1;
      out.planes.push_back(std::move(plane));
      ++next_id;
    }
  }
  if (options.compute_contours) {
    StageTimer contour_timer(out.timings_ms, "contours");
    for (PlaneSegment& plane : out.planes)
      compute_contour(out.labels, w, cloud.intrinsics, plane);
  }
  return out;
}

}  // namespace tunnelmap
