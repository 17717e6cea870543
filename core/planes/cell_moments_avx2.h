#pragma once
// cell_moments (cell_fits.h) eight points at a time with AVX2, chosen at run time
// (__builtin_cpu_supports), so the package still runs on any x86-64. The sums are the same to
// float rounding, not bit for bit: eight lanes add the points in another order than four.
#include <Eigen/Core>

#include "core/frame/organized_cloud.h"

namespace tunnelmap {

// True when this CPU runs the AVX2 moments (and force_sse_cell_moments is off).
bool cell_moments_avx2_available();
// Tests only: use the SSE moments even on an AVX2 CPU, to compare both paths.
void force_sse_cell_moments(bool on);

// As cell_moments: count, sums of d, d d^T (xx xy xz yy yz zz) and dz^3 about `ref`.
void cell_moments_avx2(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, const Eigen::Vector3f& ref,
                       double m[11]);

}  // namespace tunnelmap
