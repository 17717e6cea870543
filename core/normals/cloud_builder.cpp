#include "core/normals/cloud_builder.h"

#include <cmath>
#include <limits>

namespace tunnelmap {

void build_cloud(const DepthFrame& frame, const CloudOptions& options, OrganizedCloud& cloud) {
  const int w = frame.width, h = frame.height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  cloud.width = w;
  cloud.height = h;
  cloud.intrinsics = frame.intrinsics;
  cloud.points.resize(n);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float to_m = static_cast<float>(1.0 / frame.depth_units_per_m);
  const float zmin = static_cast<float>(options.min_range_m);
  const float zmax = static_cast<float>(options.max_range_m);
  // Precomputed per-column / per-row ray factors: x = (u - cx) / fx * z.
  thread_local std::vector<float> kx, ky;  // reused: no allocation per frame
  kx.resize(w), ky.resize(h);
  for (int u = 0; u < w; ++u) kx[u] = static_cast<float>((u - frame.intrinsics.cx) / frame.intrinsics.fx);
  for (int v = 0; v < h; ++v) ky[v] = static_cast<float>((v - frame.intrinsics.cy) / frame.intrinsics.fy);
  for (int v = 0; v < h; ++v) {
    const float* d = frame.depth.data() + static_cast<std::size_t>(v) * w;
    Eigen::Vector3f* p = cloud.points.data() + static_cast<std::size_t>(v) * w;
    for (int u = 0; u < w; ++u) {
      const float z = d[u] * to_m;
      // The range test also rejects 0, NaN and inf (comparisons with NaN are false).
      if (z >= zmin && z <= zmax && z > 0.0f)
        p[u] = {kx[u] * z, ky[v] * z, z};
      else
        p[u] = {nan, nan, nan};
    }
  }
}

}  // namespace tunnelmap
