#pragma once
// The per-pixel normal step of estimate_normals (integral_normals.cpp) eight pixels at a time
// with AVX2, chosen at run time (__builtin_cpu_supports), so the package still runs on any
// x86-64. The same operations in the same order as the SSE step, without FMA: bit-identical
// normals on either path.
#include <cstdint>

namespace tunnelmap {

// True when this CPU runs the AVX2 step (and force_sse_normals is off).
bool normals_avx2_available();
// Tests only: run the SSE step even on an AVX2 CPU, to compare both paths.
void force_sse_normals(bool on);

// Box means of one row as channel planes x, y, z, support (support > 0 = a mean exists),
// each readable from -r to w + r - 1 (zero padding), for rows v (mid), v - r (top), v + r (bottom).
struct MeanRows {
  const float* mid[4];
  const float* top[4];
  const float* bottom[4];
};

// Normals of pixels [0, n8) of a row, n8 = the largest multiple of 8 <= w: unit, facing the
// camera, NaN without a point, near an edge (near_edge != 0) or without tangents. `p` and `out`
// are the row's xyz triples. Returns n8; the caller finishes the row.
int normals_row_avx2(const MeanRows& means, int r, const std::uint8_t* near_edge, const float* p, float* out, int w);

}  // namespace tunnelmap
