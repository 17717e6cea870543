#pragma once
// Outer boundary of one label in a label image: Suzuki-Abe border following (outer borders
// only) without allocation.
#include <cstdint>
#include <vector>

namespace tunnelmap {

struct PixelPoint {
  int x = 0, y = 0;
  bool operator==(const PixelPoint& o) const { return x == o.x && y == o.y; }
};

// Twice the enclosed (shoelace) area of a closed polygon, unsigned; exact for pixel coordinates.
std::int64_t twice_polygon_area(const std::vector<PixelPoint>& polygon);

// The outer contour with the largest enclosed area among the 8-connected components of the
// pixels equal to `label` inside the inclusive box [u0, u1] x [v0, v1] of the row-major image
// `labels` (`width` columns); pixels outside the box count as background. Written to `contour`
// in image coordinates, chain-compressed (only the pixels where the border turns), like
// cv::findContours(RETR_EXTERNAL, CHAIN_APPROX_SIMPLE) followed by picking the contour of
// largest cv::contourArea: the same start pixel, direction and points (ties go to the
// component found last in a row-major scan, as OpenCV lists its contours bottom-up).
// A single pixel gives one point, a one-pixel line goes out and back. Empty if no pixel in the
// box carries `label`. The buffers in `scratch` only grow: no allocation in the steady state.
// Returns twice the contour's area.
struct BoundaryTraceScratch;
std::int64_t trace_largest_outer_boundary(const std::int32_t* labels, int width, std::int32_t label, int u0,
                                          int v0, int u1, int v1, std::vector<PixelPoint>& contour,
                                          BoundaryTraceScratch& scratch);
// The same with scratch of its own: allocates it on every call (tests, one-off traces).
std::int64_t trace_largest_outer_boundary(const std::int32_t* labels, int width, std::int32_t label, int u0,
                                          int v0, int u1, int v1, std::vector<PixelPoint>& contour);

// The tracer's buffers, kept by the caller (one per concurrent caller, see ContourScratch).
struct BoundaryTraceScratch {
  // A traced border: the first `count` points of `points`, whose size only grows (so refilling
  // it neither allocates nor re-initialises in the steady state).
  struct Chain {
    std::vector<PixelPoint> points;
    int count = 0;
  };
  std::vector<std::uint8_t> bytes;                // the box's mask, a byte per pixel
  std::vector<std::uint64_t> foreground, traced;  // the box's bit rows
  Chain trace, best;                              // the border being followed, the largest so far
};

}  // namespace tunnelmap
