#include "core/planes/residual_growth.h"

#include <algorithm>
#include <cmath>

#include "core/planes/cell_fits.h"       // smallest_eigenvector
#include "core/planes/grazing_growth.h"  // grid_cannot_connect
#include "core/planes/plane_model.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

namespace {

// The pass keeps its marks in the label image itself (0 = free) and clears them at the end:
// a pixel tried as a seed (free, may still join a region) and one in the growing region.
constexpr std::int32_t kTried = -1, kInRegion = -2, kRejected = -3, kBlocked = -4;
// Once the region's model is settled it moves too little for a pixel that failed its tests to
// pass from the next member: the pixel is not retested for this region (as RegionGrower).
constexpr std::size_t kSettledModel = 64;
// A region at least 5 pixels across both ways is no line of pixels, whose normal is free to
// turn about the line: its plane is settled at 24 members, and a facing one is dropped then
// (0.06 ms less on the office frame; lab and field recall unchanged).
constexpr std::size_t kSettledBlob = 24;
constexpr int kMinBlobSide = 5;
constexpr int kWindow = 2;            // seed window: (2 kWindow + 1)^2 pixels
constexpr int kMinWindowPoints = 12;  // free pixels of it for a fit
constexpr int kSeedStride = 2;        // seeds tried on every second pixel and row
constexpr double kMinIncidenceDeg = 75.0;      // a seed window's plane at least this far from facing the camera
constexpr double kMinCellIncidenceDeg = 60.0;  // and its cell's points as a whole
constexpr double kQuickIncidenceDeg = 60.0;
constexpr double kMaxRegionIncidenceDeg = 70.0;  // a settled region facing the camera more than this is dropped
constexpr double kMaxNoiseM = 0.004;
constexpr std::size_t kRefitFraction = 16;

// A sliver seen edge-on recedes from the camera: along the line of sight its points spread
// over far more than the sensor's noise. The pixels beside a depth edge (a diaphragm's manhole
// rim) lie at one depth, yet their 5 x 5 windows straddle the jump and look grazing; their
// strip's plane turns freely about the strip (on the simulated rim, 76-80 degrees of incidence
// in any direction), so it is no surface of its own.
constexpr double kMinRecedingNoises = 3.0;

bool recedes_from_the_camera(const PlaneModel& model, double noise_per_m2) {
  const Eigen::Vector3d centroid = model.mean_point();
  const double z2 = centroid.squaredNorm();
  const Eigen::Vector3d sight = centroid / std::sqrt(z2);
  const double spread2 = sight.dot(model.covariance() * sight);  // variance along the sight line
  const double noise = kMinRecedingNoises * noise_per_m2 * z2;
  return spread2 > noise * noise;
}

bool is_free(std::int32_t label) { return label == 0 || label == kTried; }

struct WindowPlane {
  Eigen::Vector3d n;
  Eigen::Vector3d mean;
  double mse = 0.0;
};

// The least-squares plane of the free valid pixels in the window around (u, v) (inside the image).
bool fit_window(const OrganizedCloud& cloud, const std::vector<std::int32_t>& labels, int u, int v,
                WindowPlane& out) {
  const Eigen::Vector3f ref = cloud.points[cloud.index(u, v)];
  float cnt = 0, s[3] = {0, 0, 0}, ss[6] = {0, 0, 0, 0, 0, 0};
  for (int dv = -kWindow; dv <= kWindow; ++dv)
    for (int du = -kWindow; du <= kWindow; ++du) {
      const std::size_t i = cloud.index(u + du, v + dv);
      if (!is_free(labels[i]) || !OrganizedCloud::valid(cloud.points[i])) continue;
      const Eigen::Vector3f d = cloud.points[i] - ref;
      cnt += 1, s[0] += d.x(), s[1] += d.y(), s[2] += d.z();
      ss[0] += d.x() * d.x(), ss[1] += d.x() * d.y(), ss[2] += d.x() * d.z();
      ss[3] += d.y() * d.y(), ss[4] += d.y() * d.z(), ss[5] += d.z() * d.z();
    }
  if (cnt < kMinWindowPoints) return false;
  const Eigen::Vector3d m(s[0] / cnt, s[1] / cnt, s[2] / cnt);
  const double c = cnt;
  const double scatter[6] = {ss[0] - c * m.x() * m.x(), ss[1] - c * m.x() * m.y(), ss[2] - c * m.x() * m.z(),
                             ss[3] - c * m.y() * m.y(), ss[4] - c * m.y() * m.z(), ss[5] - c * m.z() * m.z()};
  if (!smallest_eigenvector(scatter, out.n)) return false;
  out.mean = ref.cast<double>() + m;
  if (out.n.dot(out.mean) > 0) out.n = -out.n;  // face the camera
  const Eigen::Vector3d& n = out.n;
  const double spread = n.x() * (n.x() * scatter[0] + 2 * n.y() * scatter[1] + 2 * n.z() * scatter[2]) +
                        n.y() * (n.y() * scatter[3] + 2 * n.z() * scatter[4]) + n.z() * n.z() * scatter[5];
  out.mse = std::max(0.0, spread / c);
  return true;
}

// The incidence of the window's central differences is below kQuickIncidenceDeg: no need to fit
// it (most windows of the residual face the camera).
bool clearly_facing(const OrganizedCloud& cloud, int u, int v, const Eigen::Vector3f& p, float cos_quick) {
  const Eigen::Vector3f& a = cloud.points[cloud.index(u + kWindow, v)];
  const Eigen::Vector3f& b = cloud.points[cloud.index(u - kWindow, v)];
  const Eigen::Vector3f& c = cloud.points[cloud.index(u, v + kWindow)];
  const Eigen::Vector3f& e = cloud.points[cloud.index(u, v - kWindow)];
  if (!OrganizedCloud::valid(a) || !OrganizedCloud::valid(b) || !OrganizedCloud::valid(c) ||
      !OrganizedCloud::valid(e))
    return false;
  const Eigen::Vector3f n = (a - b).cross(c - e);
  return std::abs(n.dot(p)) > cos_quick * n.norm() * p.norm();
}

}  // namespace

int grow_residual_slivers(const OrganizedCloud& cloud, const GrowOptions& options, const CellGrid& grid,
                          const std::vector<std::int32_t>& cell_labels, PlaneSegments& out,
                          ResidualGrowthScratch& scratch, ContourBufferPool& pool) {
  const int w = cloud.width, h = cloud.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const double noise_per_m2 = grid.noise_per_m2;
  const int cell_px = grid.cell_px;
  if (n == 0 || out.labels.size() != n || cloud.points.size() != n ||
      cell_labels.size() != grid.cells.size())
    return 0;
  std::vector<std::int32_t>& labels = out.labels;
  std::vector<std::int32_t>& queue = scratch.queue;
  std::vector<std::int32_t>& touched = scratch.touched;
  std::vector<std::pair<std::int32_t, std::int32_t>>& rejected = scratch.rejected;
  touched.clear();

  const double eps = options.distance_m, eps2 = eps * eps;
  const float eps2f = static_cast<float>(eps2);
  const float cand2 = static_cast<float>(options.candidate_distance_m * options.candidate_distance_m);
  const float focal = static_cast<float>(cloud.intrinsics.fx);
  const int reach = std::max(1, cell_px / 2);
  const double fxfy = cloud.intrinsics.fx * cloud.intrinsics.fy;
  // Where the sensor's noise exceeds epsilon / 2 (or 4 mm), a window within epsilon / 2 of a
  // plane at grazing incidence is a step of the disparity quantisation, not a surface.
  const double max_noise = std::min(0.5 * eps, kMaxNoiseM);
  const double cos_seed = std::cos(kMinIncidenceDeg * M_PI / 180.0);
  const double cos_cell = std::cos(kMinCellIncidenceDeg * M_PI / 180.0);
  const double cos_region = std::cos(kMaxRegionIncidenceDeg * M_PI / 180.0);
  const float cos_quick = static_cast<float>(std::cos(kQuickIncidenceDeg * M_PI / 180.0));
  const int step_u[16] = {1, -1, 0, 0, 1, 1, -1, -1, 2, -2, 0, 0, 2, 2, -2, -2};
  const int step_v[16] = {0, 0, 1, -1, 1, -1, 1, -1, 0, 0, 2, -2, 2, -2, 2, -2};
  int step_i[16];
  for (int k = 0; k < 16; ++k) step_i[k] = step_v[k] * w + step_u[k];

  std::size_t kept = out.planes.size();
  std::int32_t next_id = static_cast<std::int32_t>(kept) + 1;
  int added = 0;
  // Seeds lie in the cells no plane took (a sliver's cells fit no plane); the pixels they grow
  // over may lie in any cell.
  for (int ci = 0; ci < static_cast<int>(cell_labels.size()); ++ci) {
    const CellFit& cell = grid.cells[ci];
    if (cell_labels[ci] != 0 || cell.count < kMinWindowPoints) continue;
    // A cell whose points as a whole face the camera holds no sliver seen edge-on.
    if (cell.fitted && std::abs(cell.normal.dot(cell.mean)) > cos_cell * cell.mean.norm()) continue;
    const int cu = ci % grid.cols, cv = ci / grid.cols;
    const int sv0 = std::max(kWindow, cv * cell_px), sv1 = std::min(h - kWindow, (cv + 1) * cell_px);
    const int su0 = std::max(kWindow, cu * cell_px), su1 = std::min(w - kWindow, (cu + 1) * cell_px);
    for (int v = sv0; v < sv1; v += kSeedStride)
    for (int u = su0; u < su1; u += kSeedStride) {
      const std::size_t seed = cloud.index(u, v);
      const Eigen::Vector3f& ps = cloud.points[seed];
      // Each lattice pixel is looked at once: only pixels of a dropped region need a mark
      // that keeps them from seeding.
      if (labels[seed] != 0 || !OrganizedCloud::valid(ps)) continue;
      if (noise_per_m2 * ps.squaredNorm() > max_noise || clearly_facing(cloud, u, v, ps, cos_quick)) continue;
      WindowPlane fit;
      if (!fit_window(cloud, labels, u, v, fit) || fit.mse > 0.25 * eps2) continue;
      if (std::abs(fit.n.dot(fit.mean)) > cos_seed * fit.mean.norm()) continue;  // not seen edge-on
      if (!grid_cannot_connect(ps, fit.n.cast<float>(), reach, focal, static_cast<float>(options.candidate_distance_m)))
        continue;
      // Eq. 4: the model's mean point moves with every join; its least-squares direction is
      // refitted whenever the region has grown by a sixteenth.
      PlaneModel model;
      Eigen::Vector3d normal = fit.n;
      const Eigen::Vector3f normal_f = normal.cast<float>();
      queue.clear();
      const auto join = [&](std::size_t i) {
        labels[i] = kInRegion;
        queue.push_back(static_cast<std::int32_t>(i));
        model.add(cloud.points[i], normal_f);
      };
      touched.push_back(static_cast<std::int32_t>(seed));
      join(seed);
      double d = -normal.dot(fit.mean);
      Eigen::Vector3f nf = normal_f;
      float df = static_cast<float>(d);
      std::size_t fitted = 1;
      int bu0 = u, bv0 = v, bu1 = u, bv1 = v;
      bool facing = false;
      for (std::size_t head = 0; head < queue.size() && !facing; ++head) {
        const int q = queue[head];
        const int qu = q % w, qv = q / w;
        const Eigen::Vector3f& pq = cloud.points[q];
        const bool inside = qu >= 2 && qv >= 2 && qu < w - 2 && qv < h - 2;
        for (int k = 0; k < 16; ++k) {
          // The 8 neighbours, and the pixel beyond a neighbour without a point (a sliver seen
          // edge-on has dropouts between its pixels).
          const int ru = qu + step_u[k], rv = qv + step_v[k];
          if (!inside && (ru < 0 || rv < 0 || ru >= w || rv >= h)) continue;
          if (k >= 8 && OrganizedCloud::valid(cloud.points[static_cast<std::size_t>(q + step_i[k - 8])])) continue;
          const std::size_t r = static_cast<std::size_t>(q + step_i[k]);
          if (!is_free(labels[r])) continue;
          const Eigen::Vector3f& pr = cloud.points[r];
          if (!OrganizedCloud::valid(pr) || (pr - pq).squaredNorm() > cand2) continue;
          const float off = nf.dot(pr) + df;
          if (off * off > eps2f) {
            if (queue.size() >= kSettledModel) {
              rejected.push_back({static_cast<std::int32_t>(r), labels[r]});
              labels[r] = kRejected;
            }
            continue;
          }
          if (labels[r] == 0) touched.push_back(static_cast<std::int32_t>(r));
          join(r);
          bu0 = std::min(bu0, ru), bv0 = std::min(bv0, rv), bu1 = std::max(bu1, ru), bv1 = std::max(bv1, rv);
          if (queue.size() >= 8 && queue.size() >= fitted + std::max<std::size_t>(1, fitted / kRefitFraction)) {
            const Eigen::Matrix3d c = model.covariance();
            const double cov[6] = {c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)};
            Eigen::Vector3d refit;
            if (smallest_eigenvector(cov, refit)) normal = refit.dot(normal) < 0 ? -refit : refit;
            fitted = queue.size();
            // A region that turns out to face the camera is no sliver: the cells had their
            // chance at it, and growing it pixel by pixel would cost what the cells save.
            const Eigen::Vector3d centroid = model.mean_point();
            const bool blob = std::min(bu1 - bu0, bv1 - bv0) + 1 >= kMinBlobSide;
            if ((queue.size() >= kSettledModel || (blob && queue.size() >= kSettledBlob)) &&
                std::abs(normal.dot(centroid)) > cos_region * centroid.norm()) {
              facing = true;
              break;
            }
          }
          d = -normal.dot(model.mean_point());
          nf = normal.cast<float>(), df = static_cast<float>(d);
        }
      }
      for (const auto& [i, old] : rejected) labels[i] = old;
      rejected.clear();
      bool keep = !facing && model.count() >= options.min_points && recedes_from_the_camera(model, noise_per_m2);
      if (keep) {
        if (kept == out.planes.size()) add_plane_slot(out.planes, pool);
        fill_segment_statistics(out.planes[kept], model, options, fxfy, normal);
        keep = out.planes[kept].area_m2 >= options.min_area_m2;
      }
      if (!keep) {  // free again for later regions, but never a seed; a region facing the camera is no sliver at all
        for (const std::int32_t q : queue) labels[q] = facing ? kBlocked : kTried;
        continue;
      }
      PlaneSegment& plane = out.planes[kept];
      plane.id = next_id;
      plane.edge_on = true;
      plane.bbox_u0 = bu0, plane.bbox_v0 = bv0, plane.bbox_u1 = bu1, plane.bbox_v1 = bv1;
      for (const std::int32_t q : queue) labels[q] = next_id;
      ++kept, ++next_id, ++added;
    }
  }
  for (const std::int32_t i : touched)
    if (labels[i] < 0) labels[i] = 0;
  shrink_plane_slots(out.planes, kept, pool);
  return added;
}

}  // namespace tunnelmap
