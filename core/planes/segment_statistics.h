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

}  // namespace tunnelmap
