// The vectorised cell and block fits (cell_fit_batch.h): the same bits on the AVX2 and SSE2
// paths, and the same planes as the scalar eigenvector and moments formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "core/planes/cell_fit_batch.h"
#include "core/planes/cell_fit_kernels.h"
#include "core/planes/cell_fits.h"

using namespace tunnelmap;

namespace {

// `cells` random point sets about random references: mostly noisy planes at 0.5-5 m, some
// lines (rank 1), some single points and some empty cells. Returns the kCellFields arrays.
std::vector<double> random_cell_moments(std::size_t cells, std::size_t stride, std::mt19937& rng) {
  std::vector<double> a(static_cast<std::size_t>(kCellFields) * stride, 0.0);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t i = 0; i < cells; ++i) {
    const int kind = static_cast<int>(i % 10);  // 0: empty, 1: one point, 2: a line, else a plane
    const int points = kind == 0 ? 0 : kind == 1 ? 1 : 64;
    // Each draw its own statement: the order of a call's arguments is the compiler's.
    Eigen::Vector3d ref, n;
    for (int k = 0; k < 3; ++k) ref[k] = uni(rng);
    ref.z() = 2.75 + 2.25 * ref.z();
    for (int k = 0; k < 2; ++k) n[k] = uni(rng);
    n.z() = -1.0;
    n.normalize();
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    double m[11] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < points; ++k) {
      const double s = 0.004 * (k % 8 - 3.5), t = kind == 2 ? 0.0 : 0.004 * (k / 8 - 3.5);
      const Eigen::Vector3d d = s * e1 + t * e2 + (kind == 2 ? 0.0 : 0.002 * noise(rng)) * n;
      const double v[11] = {1, d.x(), d.y(), d.z(), d.x() * d.x(), d.x() * d.y(), d.x() * d.z(),
                            d.y() * d.y(), d.y() * d.z(), d.z() * d.z(), d.z() * d.z() * d.z()};
      for (int j = 0; j < 11; ++j) m[j] += v[j];
    }
    for (int j = 0; j < 11; ++j) a[(kMoment0 + j) * stride + i] = m[j];
    for (int j = 0; j < 3; ++j) a[(kRefX + j) * stride + i] = ref(j);
  }
  return a;
}

}  // namespace

TEST(CellFitBatch, Avx2AndSse2GiveTheSameBitsAndTheScalarPlanes) {
  std::mt19937 rng(7);
  const std::size_t cells = 203, stride = padded_cells(cells);  // a partial last vector
  ASSERT_EQ(stride % kCellLanes, 0u);
  const std::vector<double> input = random_cell_moments(cells, stride, rng);
  std::vector<double> avx2 = input, sse2 = input;
  fit_cell_planes(avx2.data(), stride, 32.0);
  force_sse_cell_fit_batch(true);
  fit_cell_planes(sse2.data(), stride, 32.0);
  force_sse_cell_fit_batch(false);
  for (std::size_t k = 0; k < avx2.size(); ++k) ASSERT_EQ(avx2[k], sse2[k]) << "field " << k / stride;

  int fitted = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    const auto at = [&](int field) { return avx2[field * stride + i]; };
    const int kind = static_cast<int>(i % 10);
    double s[6];
    for (int k = 0; k < 6; ++k) s[k] = at(kScatter0 + k);
    Eigen::Vector3d n;
    const bool unique = smallest_eigenvector(s, n);
    EXPECT_EQ(at(kFitted) > 0, kind >= 3) << "cell " << i;
    EXPECT_EQ(at(kFitted) > 0, unique && at(kMoment0) >= 32.0) << "cell " << i;
    if (at(kFitted) == 0) {
      EXPECT_EQ(at(kNormalX), 0.0);
      continue;
    }
    ++fitted;
    const Eigen::Vector3d mean(at(kMeanX), at(kMeanY), at(kMeanZ));
    if (n.dot(mean) > 0) n = -n;
    EXPECT_EQ(Eigen::Vector3d(at(kNormalX), at(kNormalY), at(kNormalZ)), n) << "cell " << i;
    // 2 mm of noise along the normal: an mse of about 4 mm^2.
    EXPECT_NEAR(std::sqrt(at(kMse)), 0.002, 0.0008) << "cell " << i;
    EXPECT_GT(at(kNormalSe), 0.0);
    EXPECT_LT(at(kNormalSe), 0.5);
  }
  EXPECT_EQ(fitted, 140);  // 7 of every 10 cells; cells 200-202 are empty, a point, a line
}

TEST(CellFitBatch, BlockFitsAgreeOnBothPathsAndRejectAStep) {
  // Two blocks: nine cells of one plane z = 2, and nine of which three stand 8 mm proud.
  const std::size_t stride = kCellLanes;
  std::vector<double> b(static_cast<std::size_t>(kBlockFields) * stride, 0.0), own(3 * stride, 0.0);
  for (std::size_t blk = 0; blk < 2; ++blk) {
    double sums[kBlockSums] = {};
    for (int c = 0; c < 9; ++c)
      for (int k = 0; k < 64; ++k) {
        const double x = 0.03 * (c % 3) + 0.004 * (k % 8), y = 0.03 * (c / 3) + 0.004 * (k / 8);
        const double z = 2.0 - (blk == 1 && c % 3 == 2 ? 0.008 : 0.0) + 0.0005 * ((k * 7919) % 5 - 2);
        const double v[kBlockSums] = {k == 0 ? 1.0 : 0.0, 1, x, y, z, x * x, x * y, x * z, y * y, y * z, z * z,
                                      0.0, 0.0};
        for (int j = 0; j < kBlockSums; ++j) sums[j] += v[j];
      }
    sums[kOwnResidual] = 9 * 64 * 0.0005 * 0.0005 * 2;  // the cells' own residual (mse 2 x 0.25 mm^2)
    sums[kBound] = 9 * 64 * 0.004 * 0.004;              // within epsilon / 2 on RMS
    for (int j = 0; j < kBlockSums; ++j) b[j * stride + blk] = sums[j];
    own[2 * stride + blk] = -1.0;  // the cells' own normals face the camera
  }
  std::vector<double> sse2 = b;
  fit_block_planes(b.data(), own.data(), stride, 64.0, 0.0005 * 0.0005);
  force_sse_cell_fit_batch(true);
  fit_block_planes(sse2.data(), own.data(), stride, 64.0, 0.0005 * 0.0005);
  force_sse_cell_fit_batch(false);
  for (std::size_t k = 0; k < b.size(); ++k) ASSERT_EQ(b[k], sse2[k]) << "field " << k / stride;
  EXPECT_EQ(b[kBlockFitted * stride + 0], 1.0);
  EXPECT_NEAR(b[kBlockNormalZ * stride + 0], -1.0, 1e-6);
  EXPECT_LT(b[kBlockSe * stride + 0], 0.01);
  EXPECT_EQ(b[kBlockFitted * stride + 1], 0.0);  // the 8 mm step fails the F test
  EXPECT_EQ(b[kBlockFitted * stride + 2], 0.0);  // no members
}
