#pragma once
// Stage 2b: per-pixel normals on an organised cloud with integral images (Holzer et al. 2012,
// the "average 3D gradient" variant): box means of the points from summed-area tables, the
// horizontal and vertical gradients of those means, their cross product.
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/normals/normal_options.h"  // NormalOptions

namespace tunnelmap {

// The buffers estimate_normals works in, kept by the caller so that frame after frame allocates
// nothing (Pipeline keeps one per FrameResult, see FrameScratch). One per concurrent caller.
// Points and their box means are (x, y, z, support) quadruples, one SSE register per pixel: a
// box sum of the four channels is then one vector addition per step. The float images are
// ring buffers of a few rows, filled and consumed in one streaming pass over the frame, so the
// working set stays in the cache instead of making seven passes over ~5 MB images.
struct NormalScratch {
  std::vector<float> q_ring;     // quadruples of the last rows (x, y, z, 1; 0 where invalid)
  std::vector<float> mean_ring;  // box means of the last rows, channel planes x, y, z, support (1 or 0)
  std::vector<float> mean_aos;   // the current row's means as quadruples, before the transpose
  std::vector<float> no_means;   // a row of zero support, above and below the image
  std::vector<float> inv_ring;   // inverse depth of the last rows, 0 = no measurement
  std::vector<float> acc;        // vertical box sums of the current row (4 per pixel)
  std::vector<std::uint8_t> edges, row_dilated, near_edge;  // full images, one byte per pixel
  std::vector<int> edge_count;
};

// Fills cloud.normals (unit, facing the camera; NaN at edges/invalid pixels).
void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud, NormalScratch& scratch);
// The same with scratch of its own: allocates it on every call (one-off frames, tests).
void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud);

}  // namespace tunnelmap
