#pragma once
// Outer boundary polygons of grown planes, traced on the label image and lifted onto the plane.
#include <vector>

#include "core/frame/intrinsics.h"
#include "core/planes/boundary_trace.h"
#include "core/planes/plane_segment.h"
#include "core/planes/polygon_simplify.h"

namespace tunnelmap {

// Fills plane.contour from the pixels labelled plane.id inside its bounding box (clipped to
// the image): the largest outer contour, simplified to `tolerance_px`, each vertex's ray
// intersected with the plane. The same vertices as OpenCV's findContours(RETR_EXTERNAL,
// CHAIN_APPROX_SIMPLE) + largest contourArea + approxPolyDP gave (tests/core/planes/plane_contour_test.cpp),
// without allocating in the steady state: the buffers of `scratch`, plane.contour's capacity kept.
struct ContourScratch {
  std::vector<PixelPoint> outline, polygon;  // the traced border, its simplification
  BoundaryTraceScratch trace;
  SimplifyScratch simplify;
};
void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, ContourScratch& scratch, double tolerance_px = 1.0);
// The same with scratch of its own: allocates it on every call (tests, one-off planes).
void compute_contour(const std::vector<std::int32_t>& labels, int width, const Intrinsics& K,
                     PlaneSegment& plane, double tolerance_px = 1.0);

}  // namespace tunnelmap
