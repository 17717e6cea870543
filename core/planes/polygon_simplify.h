#pragma once
// Douglas-Peucker simplification of closed pixel polygons without allocation.
#include <utility>
#include <vector>

#include "core/planes/boundary_trace.h"

namespace tunnelmap {

// Simplifies the closed polygon `polygon` so that no dropped vertex lies farther than
// `tolerance` (pixels) from the kept chord over it; writes the kept vertices to `out`.
// Same result as OpenCV 4.6's cv::approxPolyDP(polygon, out, tolerance, true): the recursion
// starts from the pair of "far apart" vertices its three farthest-point passes find (starting
// at vertex 0), measures distances to the chord's line, and a final pass drops vertices on
// nearly straight diagonal runs. (Later OpenCV releases measure the distance to the chord's
// segment rather than its line, so their results can differ.) A polygon that fits within
// `tolerance` of one of its vertices becomes that single vertex. The buffers in `scratch` only
// grow: no allocation in the steady state.
struct SimplifyScratch {
  std::vector<std::pair<int, int>> stack;  // chords still to split (first, last vertex)
};
void simplify_closed_polygon(const std::vector<PixelPoint>& polygon, double tolerance, std::vector<PixelPoint>& out,
                             SimplifyScratch& scratch);
// The same with scratch of its own: allocates it on every call (tests, one-off polygons).
void simplify_closed_polygon(const std::vector<PixelPoint>& polygon, double tolerance, std::vector<PixelPoint>& out);

}  // namespace tunnelmap
