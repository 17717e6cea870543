#pragma once
// assign_to_nearest_plane (border_assignment.h) eight pixels at a time with AVX2, chosen at run
// time (__builtin_cpu_supports), so the package still runs on any x86-64. The same labels as
// the SSE kernel (the same operations per pixel, no FMA); the tallies' sums agree to float
// rounding (eight lanes add the pixels in another order than four).
#include <Eigen/Core>
#include <cstdint>

#include "core/frame/organized_cloud.h"
#include "core/planes/border_assignment.h"

namespace tunnelmap {

// True when this CPU runs the AVX2 kernel (and force_sse_border_assignment is off).
bool border_assignment_avx2_available();
// Tests only: use the SSE kernel even on an AVX2 CPU, to compare both.
void force_sse_border_assignment(bool on);

// As assign_to_nearest_plane, for cells at least 8 pixels wide.
void assign_to_nearest_plane_avx2(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1,
                                  const Eigen::Vector4f* planes, const std::int32_t* cand, int ncand, float eps,
                                  std::int32_t* labels, PixelTally* tallies);

}  // namespace tunnelmap
