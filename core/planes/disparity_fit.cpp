#include "core/planes/disparity_fit.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap {

void DisparityMoments::add_cell(const double s[kDisparitySums], double count, int u0, int v0, const Intrinsics& k) {
  if (!(count > 0)) return;
  // x' = (u - cx) / fx = ax + du / fx about the corner's ax, in double from here on.
  const double ix = 1.0 / k.fx, iy = 1.0 / k.fy;
  const double ax = (u0 - k.cx) * ix, ay = (v0 - k.cy) * iy;
  const double sx = s[kSumU] * ix, sy = s[kSumV] * iy, sw = s[kSumW];
  n += count;
  x += sx + ax * count, y += sy + ay * count, w += sw;
  xx += s[kSumUU] * ix * ix + 2 * ax * sx + ax * ax * count;
  xy += s[kSumUV] * ix * iy + ax * sy + ay * sx + ax * ay * count;
  yy += s[kSumVV] * iy * iy + 2 * ay * sy + ay * ay * count;
  xw += s[kSumUW] * ix + ax * sw, yw += s[kSumVW] * iy + ay * sw;
}

bool DisparityMoments::plane(Eigen::Vector3d& normal, double& d) const {
  if (n < 3) return false;
  const double mx = x / n, my = y / n, mw = w / n;
  const double sxx = xx - x * mx, sxy = xy - x * my, syy = yy - y * my;
  const double sxw = xw - x * mw, syw = yw - y * mw;
  const double det = sxx * syy - sxy * sxy;
  // Pixels along one line of the image span one direction only: a determinant that is rounding
  // next to the spread's scale (two rows of 50 pixels give 1e-3 of it).
  if (!(det > 1e-9 * (sxx + syy) * (sxx + syy))) return false;
  const double a = (sxw * syy - syw * sxy) / det;
  const double b = (syw * sxx - sxw * sxy) / det;
  const double c = mw - a * mx - b * my;
  // 1/z = a x' + b y' + c  <=>  a x + b y + c z = 1: the plane (a, b, c).p - 1 = 0, whose
  // normal facing the camera is -(a, b, c) / |(a, b, c)| with d = 1 / |(a, b, c)|.
  const double len = std::sqrt(a * a + b * b + c * c);
  if (!(len > 1e-9) || !std::isfinite(len)) return false;
  normal = Eigen::Vector3d(-a, -b, -c) / len;
  d = 1.0 / len;
  return true;
}

void add_cell_points(const OrganizedCloud& cloud, const CellGrid& grid, const std::vector<std::int32_t>& cells,
                     DisparityMoments& m) {
  const int c = grid.cell_px;
  for (const std::int32_t cell : cells) {
    const int u0 = (cell % grid.cols) * c, v0 = (cell / grid.cols) * c;
    const int u1 = std::min(u0 + c, cloud.width), v1 = std::min(v0 + c, cloud.height);
    // In float about the cell's corner (a cell's sums are small), in pixel units.
    float n = 0, s[kDisparitySums] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (int v = v0; v < v1; ++v) {
      const Eigen::Vector3f* row = cloud.points.data() + cloud.index(0, v);
      const float dv = static_cast<float>(v - v0);
      for (int u = u0; u < u1; ++u) {
        const float z = row[u].z();
        if (!(z == z)) continue;  // NaN marks an invalid pixel
        const float w = 1.0f / z, du = static_cast<float>(u - u0);
        n += 1;
        s[kSumU] += du, s[kSumV] += dv, s[kSumUU] += du * du, s[kSumUV] += du * dv, s[kSumVV] += dv * dv;
        s[kSumW] += w, s[kSumUW] += du * w, s[kSumVW] += dv * w;
      }
    }
    const double sums[kDisparitySums] = {s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7]};
    m.add_cell(sums, n, u0, v0, cloud.intrinsics);
  }
}

}  // namespace tunnelmap
