#pragma once
// A plane segment's reported statistics from its eq. 3-4 model: centroid, mean and
// least-squares normals, offset, RMS and area. Shared by the every-pixel grower and the
// coarse-to-fine refinement, so both paths report the same quantities the same way.
#include "core/planes/plane_model.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct GrowOptions;

// Overwrites everything in `plane` except the id, contour storage and bounding box. Area: each
// pixel's footprint on the plane is z^3 / (fx fy |n.p|), and n.p = -offset on the plane.
void fill_segment_statistics(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options,
                             double fxfy);
// The same with the model's least-squares normal already known (unit, facing like the mean
// normal): its RMS is taken along it, no eigen-solver runs.
void fill_segment_statistics(PlaneSegment& plane, const PlaneModel& model, const GrowOptions& options, double fxfy,
                             const Eigen::Vector3d& least_squares_normal);

}  // namespace tunnelmap
