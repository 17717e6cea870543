#pragma once
// Outer boundary polygons of grown planes, traced on the label image and lifted onto the plane.
#include "core/frame/intrinsics.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

// Fills plane.contour from the pixels labelled plane.id inside its bounding box (clipped to
// the image): the largest outer contour, simplified to `tolerance_px`, each vertex's ray
// intersected with the plane. The same vertices as OpenCV's findContours(RETR_EXTERNAL,
// CHAIN_APPROX_SIMPLE) + largest contourArea + approxPolyDP gave (tests/core/planes/plane_contour_test.cpp),
// without allocating in the steady state: per-thread buffers, plane.contour's capacity kept.
void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, double tolerance_px = 1.0);

}  // namespace tunnelmap
