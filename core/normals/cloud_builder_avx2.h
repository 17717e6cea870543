#pragma once
// build_cloud's row step eight pixels at a time with AVX2, chosen at run time
// (__builtin_cpu_supports), so the package still runs on any x86-64. The points are the same
// bits as the SSE step's: the same division, product and range test per pixel.

namespace tunnelmap {

// True when this CPU runs the AVX2 step (and force_sse_cloud_builder is off).
bool cloud_builder_avx2_available();
// Tests only: use the SSE step even on an AVX2 CPU, to compare both.
void force_sse_cloud_builder(bool on);

// Back-projects pixels [0, u_end) of one row, u_end the largest multiple of 8 within `w`:
// p = (kx[u] z, ky z, z) with z = depth / units, NaN outside [zmin, zmax] or where z is not
// positive. Returns u_end.
int build_cloud_row_avx2(const float* depth, const float* kx, float ky, int w, float units, float zmin, float zmax,
                         float* points);

}  // namespace tunnelmap
