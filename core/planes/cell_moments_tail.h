#pragma once
// The scalar step shared by cell_moments' SSE and AVX2 kernels: pixels [u, u1) of a row that
// the vector step left over, added to the 11 moment sums about `ref` (see cell_moments).
#include <Eigen/Core>

namespace tunnelmap {

inline void add_tail_moments(const float* row, int u, int u1, const Eigen::Vector3f& ref, float tail[11]) {
  for (; u < u1; ++u) {
    const float* p = row + 3 * u;
    if (!(p[2] == p[2])) continue;  // NaN marks an invalid pixel
    const float dx = p[0] - ref.x(), dy = p[1] - ref.y(), dz = p[2] - ref.z();
    const float t[11] = {1, dx, dy, dz, dx * dx, dx * dy, dx * dz, dy * dy, dy * dz, dz * dz, dz * dz * dz};
    for (int k = 0; k < 11; ++k) tail[k] += t[k];
  }
}

}  // namespace tunnelmap
