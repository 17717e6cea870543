#pragma once
// The kernels of cell_fit_kernels.h over a whole grid of cells, four cells per instruction with
// AVX2 where the CPU has it (chosen at run time, so the package runs on any x86-64), two with
// SSE2 otherwise. Both give the same bits.
#include <cstddef>

namespace tunnelmap {

// fit_cell_planes_kernel on the kCellFields arrays at `a`, `stride` (a multiple of
// kCellLanes) apart.
void fit_cell_planes(double* a, std::size_t stride, double min_points);
// fit_block_planes_kernel on the kBlockFields arrays at `b`, `stride` apart.
void fit_block_planes(double* b, const double* own_normal, std::size_t stride, double max_f, double noise_floor2);

// Tests only: the SSE2 variants even on an AVX2 CPU, to compare both.
void force_sse_cell_fit_batch(bool on);

}  // namespace tunnelmap
