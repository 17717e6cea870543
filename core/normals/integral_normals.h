#pragma once
// Stage 2b: per-pixel normals on an organised cloud with integral images (Holzer et al. 2012,
// the "average 3D gradient" variant): box means of the points from summed-area tables, the
// horizontal and vertical gradients of those means, their cross product.
#include "core/frame/organized_cloud.h"

namespace tunnelmap {

struct NormalOptions {
  int smoothing_px = 10;           // normals.smoothing_px: side of the box window
  double max_depth_change = 0.15;  // normals.max_depth_change: relative 2nd difference of inverse depth = edge
};

// Fills cloud.normals (unit, facing the camera; NaN at edges/invalid pixels).
void estimate_normals(const NormalOptions& options, OrganizedCloud& cloud);

}  // namespace tunnelmap
