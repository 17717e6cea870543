#include "core/planes/segment_statistics.h"

#include <algorithm>
#include <cmath>

#include "core/planes/plane_growing.h"

namespace tunnelmap {

namespace {

void fill(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options, double fxfy,
          const Eigen::Vector3d& lsq, double rms) {
  plane.contour.clear();
  plane.edge_on = false;
  plane.points = static_cast<int>(model.count());
  plane.centroid = model.mean_point();
  plane.mean_normal = model.mean_normal().normalized();
  plane.rms_m = rms;
  plane.normal = options.refit_normal ? lsq : plane.mean_normal;
  plane.offset_m = -plane.normal.dot(plane.centroid);
  plane.area_m2 = std::abs(plane.offset_m) > 1e-9 ? model.sum_z_cubed() / (fxfy * std::abs(plane.offset_m)) : 0.0;
}

}  // namespace

void fill_segment_statistics(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options,
                             double fxfy) {
  double rms = 0;
  const Eigen::Vector3d lsq = model.least_squares_normal(&rms);
  fill(plane, model, options, fxfy, lsq, rms);
}

void fill_segment_statistics(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options, double fxfy,
                             const Eigen::Vector3d& least_squares_normal) {
  const Eigen::Vector3d& n = least_squares_normal;
  fill(plane, model, options, fxfy, n, std::sqrt(std::max(0.0, n.dot(model.covariance() * n))));
}

}  // namespace tunnelmap
