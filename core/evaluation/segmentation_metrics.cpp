#include "core/evaluation/segmentation_metrics.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/util/error.h"

namespace tunnelmap {

SegmentationScore& SegmentationScore::operator+=(const SegmentationScore& o) {
  planes += o.planes;
  correct_planes += o.correct_planes;
  surfaces += o.surfaces;
  found_surfaces += o.found_surfaces;
  return *this;
}

SegmentationOptions SegmentationOptions::by_size(int min_points, double min_area_m2) {
  SegmentationOptions o;
  o.overlap = 0.5;  // plus the strict-majority rule: > 50 %
  o.min_surface_pixels = 0;
  o.min_surface_points = min_points;
  o.min_surface_area_m2 = min_area_m2;
  return o;
}

namespace {

// Per true surface: pixel counts and the sums of its visible points for the plane fit.
struct SurfaceAccumulator {
  long truth_pixels = 0, pixels = 0, labelled = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
  double area = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

// Least-squares plane normal of the accumulated points, facing the camera (n.centroid < 0).
Eigen::Vector3d fit_normal(const SurfaceAccumulator& a) {
  const Eigen::Vector3d mean = a.sum / double(a.pixels);
  const Eigen::Matrix3d cov = a.sum_outer / double(a.pixels) - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d n = eig.eigenvectors().col(0);  // smallest eigenvalue first
  return n.dot(mean) > 0 ? Eigen::Vector3d(-n) : n;
}

bool planar(int t, const SegmentationOptions& o) { return t != 0 && t != o.non_planar_id; }

SegmentationScore score(const PlaneSegments& planes, const std::vector<std::uint16_t>& truth,
                        const OrganizedCloud* cloud, const SegmentationOptions& o,
                        std::vector<SurfaceDetail>* details) {
  if (truth.size() != planes.labels.size())
    throw InputError("", "ground-truth surface image has " + std::to_string(truth.size()) +
                             " pixels but the plane labels " + std::to_string(planes.labels.size()));
  if (cloud && cloud->points.size() != truth.size())
    throw InputError("", "ground-truth surface image has " + std::to_string(truth.size()) +
                             " pixels but the organised cloud " + std::to_string(cloud->points.size()));
  // Pass 1: surface pixel counts and point sums; (plane, true id) pixel counts.
  std::map<int, SurfaceAccumulator> surfaces;
  std::map<std::pair<int, int>, long> pair_pixels;  // (plane id, true id) -> pixels
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const int t = truth[i];
    const int label = planes.labels[i];
    if (label > 0) ++pair_pixels[{label, t}];
    if (!planar(t, o)) continue;
    SurfaceAccumulator& a = surfaces[t];
    ++a.truth_pixels;
    if (!cloud) {
      ++a.pixels;
      a.labelled += label > 0;
      continue;
    }
    const Eigen::Vector3f& pf = cloud->points[i];
    if (!OrganizedCloud::valid(pf)) continue;
    const Eigen::Vector3d p = pf.cast<double>();
    ++a.pixels;
    a.labelled += label > 0;
    a.sum += p;
    a.sum_outer += p * p.transpose();
  }
  // Pass 2 (cloud only): the visible area on each surface's fitted plane.
  if (cloud) {
    for (auto& [t, a] : surfaces)
      if (a.pixels >= 3) a.normal = fit_normal(a);
    const double fxfy = cloud->intrinsics.fx * cloud->intrinsics.fy;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const int t = truth[i];
      if (!planar(t, o) || !OrganizedCloud::valid(cloud->points[i])) continue;
      SurfaceAccumulator& a = surfaces[t];
      const Eigen::Vector3d p = cloud->points[i].cast<double>();
      const double np = std::abs(a.normal.dot(p));
      if (np > 1e-9) a.area += p.z() * p.z() * p.z() / (fxfy * np);
    }
  }

  // Plane totals, then the overlap test per plane.
  std::map<int, long> plane_total;
  std::map<int, std::pair<int, long>> best_surface_of_plane;  // plane -> (true id, pixels)
  std::map<int, std::pair<int, long>> best_plane_of_surface;  // true id -> (plane, pixels)
  for (const auto& [key, n] : pair_pixels) {
    const auto [label, t] = key;
    plane_total[label] += n;
    if (!planar(t, o)) continue;
    auto& bs = best_surface_of_plane[label];
    if (n > bs.second) bs = {t, n};
    auto& bp = best_plane_of_surface[t];
    if (n > bp.second) bp = {label, n};
  }
  SegmentationScore s;
  std::map<int, bool> found;
  for (const PlaneSegment& p : planes.planes) {
    ++s.planes;
    const auto it = best_surface_of_plane.find(p.id);
    if (it == best_surface_of_plane.end()) continue;
    const long total = plane_total[p.id], best = it->second.second;
    // overlap share, and always a strict majority: one plane never matches two surfaces.
    if (best >= o.overlap * total && 2 * best > total) {
      ++s.correct_planes;
      found[it->second.first] = true;
    }
  }
  if (details) details->clear();
  for (const auto& [t, a] : surfaces) {
    bool counted = a.truth_pixels >= o.min_surface_pixels;
    if (cloud) counted = counted && a.pixels >= o.min_surface_points && a.area >= o.min_surface_area_m2;
    const bool was_found = found.count(t) > 0;
    if (counted) {
      ++s.surfaces;
      s.found_surfaces += was_found ? 1 : 0;
    }
    if (!details) continue;
    SurfaceDetail d;
    d.id = t;
    d.truth_pixels = a.truth_pixels;
    d.pixels = a.pixels;
    d.labelled_pixels = a.labelled;
    d.counted = counted;
    d.found = was_found;
    if (cloud && a.pixels > 0) {
      const Eigen::Vector3d centroid = a.sum / double(a.pixels);
      d.area_m2 = a.area;
      d.mean_depth_m = centroid.z();
      d.normal = a.normal;
      if (a.normal.squaredNorm() > 0)
        d.incidence_deg = std::acos(std::min(1.0, std::abs(a.normal.dot(centroid.normalized())))) * 180.0 / M_PI;
    }
    const auto bp = best_plane_of_surface.find(t);
    if (bp != best_plane_of_surface.end()) {
      d.best_plane = bp->second.first;
      d.best_plane_pixels = bp->second.second;
      d.best_plane_share = double(bp->second.second) / double(plane_total[bp->second.first]);
    }
    details->push_back(d);
  }
  return s;
}

}  // namespace

SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const SegmentationOptions& options,
                                     std::vector<SurfaceDetail>* details) {
  return score(planes, truth, nullptr, options, details);
}

SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const OrganizedCloud& cloud, const SegmentationOptions& options,
                                     std::vector<SurfaceDetail>* details) {
  return score(planes, truth, &cloud, options, details);
}

}  // namespace tunnelmap
