#include "core/planes/cell_fit_batch.h"

#include "core/planes/cell_fit_kernels.h"
#include "core/util/avx2_dispatch.h"

namespace tunnelmap {

namespace {

Avx2Dispatch dispatch;

using Sse2Lanes = double __attribute__((vector_size(16)));
using Avx2Lanes = double __attribute__((vector_size(32)));

__attribute__((target("avx2"))) void fit_cell_planes_avx2(double* a, std::size_t stride, double min_points) {
  fit_cell_planes_kernel<Avx2Lanes>(a, stride, min_points);
}

__attribute__((target("avx2"))) void fit_block_planes_avx2(double* b, const double* own_normal, std::size_t stride,
                                                            double max_f, double noise_floor2) {
  fit_block_planes_kernel<Avx2Lanes>(b, own_normal, stride, max_f, noise_floor2);
}

}  // namespace

void force_sse_cell_fit_batch(bool on) { dispatch.force_sse(on); }

void fit_cell_planes(double* a, std::size_t stride, double min_points) {
  if (dispatch.use_avx2()) return fit_cell_planes_avx2(a, stride, min_points);
  fit_cell_planes_kernel<Sse2Lanes>(a, stride, min_points);
}

void fit_block_planes(double* b, const double* own_normal, std::size_t stride, double max_f, double noise_floor2) {
  if (dispatch.use_avx2()) return fit_block_planes_avx2(b, own_normal, stride, max_f, noise_floor2);
  fit_block_planes_kernel<Sse2Lanes>(b, own_normal, stride, max_f, noise_floor2);
}

}  // namespace tunnelmap
