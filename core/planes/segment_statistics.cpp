#include "core/planes/segment_statistics.h"

#include <cmath>

#include "core/planes/plane_growing.h"

namespace tunnelmap {

void fill_segment_statistics(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options,
                             double fxfy) {
  plane.contour.clear();
  plane.edge_on = false;
  plane.points = static_cast<int>(model.count());
  plane.centroid = model.mean_point();
  plane.mean_normal = model.mean_normal().normalized();
  double rms = 0;
  const Eigen::Vector3d lsq = model.least_squares_normal(&rms);
  plane.rms_m = rms;
  plane.normal = options.refit_normal ? lsq : plane.mean_normal;
  plane.offset_m = -plane.normal.dot(plane.centroid);
  plane.area_m2 = std::abs(plane.offset_m) > 1e-9 ? model.sum_z_cubed() / (fxfy * std::abs(plane.offset_m)) : 0.0;
}

}  // namespace tunnelmap
