#include "core/io/intrinsics_estimation.h"

#include <cmath>

#include "core/util/error.h"

namespace tunnelmap {

namespace {

// Least-squares line y = slope * x + intercept from running sums.
struct LineFit {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  void add(double x, double y) {
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  bool solve(double& slope, double& intercept) const {
    const double det = n * sxx - sx * sx;
    if (!(std::abs(det) > 1e-12 * n * n)) return false;
    slope = (n * sxy - sx * sy) / det;
    intercept = (sy - slope * sx) / n;
    return std::isfinite(slope) && std::isfinite(intercept);
  }
};

}  // namespace

Intrinsics estimate_intrinsics(const std::vector<Eigen::Vector3f>& points, int width, int height,
                               const std::string& source) {
  LineFit fit_u, fit_v;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const Eigen::Vector3f& p = points[static_cast<std::size_t>(v) * width + u];
      if (!p.allFinite() || !(p.z() > 0.f)) continue;
      fit_u.add(double(p.x()) / p.z(), u);
      fit_v.add(double(p.y()) / p.z(), v);
    }
  }
  const std::string ask = "; give the camera intrinsics with --intrinsics FX,FY,CX,CY";
  if (fit_u.n < kMinPointsForIntrinsics)
    throw InputError(source, "only " + std::to_string(static_cast<long>(fit_u.n)) +
                                 " valid points, too few to estimate the intrinsics" + ask);
  Intrinsics k;
  k.width = width;
  k.height = height;
  if (!fit_u.solve(k.fx, k.cx) || !fit_v.solve(k.fy, k.cy) || !(k.fx > 0) || !(k.fy > 0))
    throw InputError(source, "cannot estimate the intrinsics from the points" + ask);
  return k;
}

}  // namespace tunnelmap
