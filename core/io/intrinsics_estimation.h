#pragma once
// Recovers pinhole intrinsics from an organised point cloud: for every valid pixel (u, v) with
// point (x, y, z), u = fx * x/z + cx and v = fy * y/z + cy; two independent line fits.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

constexpr int kMinPointsForIntrinsics = 100;

// `points`: width*height, row-major, camera frame; NaN or z <= 0 = invalid. Throws InputError
// naming `source` if there are fewer than kMinPointsForIntrinsics valid points or the fit is
// degenerate (e.g. all points on one image row or column).
Intrinsics estimate_intrinsics(const std::vector<Eigen::Vector3f>& points, int width, int height,
                               const std::string& source);

}  // namespace tunnelmap
