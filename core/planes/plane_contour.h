#pragma once
// Outer boundary polygons of grown planes, traced on the label image and lifted onto the plane.
#include "core/frame/intrinsics.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

// Fills plane.contour from the pixels labelled plane.id inside its bounding box: the largest
// outer contour, simplified to `tolerance_px`, each vertex's ray intersected with the plane.
void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, double tolerance_px = 1.0);

}  // namespace tunnelmap
