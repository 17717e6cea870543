// Border-cell assignment: every pixel of a cell to the nearest candidate plane within epsilon,
// with what each plane gained tallied on the way (count, point sums, z^3, bounding box),
// checked pixel by pixel against a plain scalar reference for 1 to 9 candidates, on the SSE
// and the AVX2 kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/planes/border_assignment.h"
#include "core/planes/border_assignment_avx2.h"
#include "tests/core/planes/hand_cloud.h"

using namespace tunnelmap;
using tunnelmap::testing::hand_cloud;

namespace {

// Points scattered about z = 2 m with a few invalid ones; candidate planes close to them.
struct Scene {
  OrganizedCloud cloud;
  std::vector<Eigen::Vector4f> planes;
};

Scene random_scene(unsigned seed, int nplanes) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f), tilt(-0.3f, 0.3f);
  Scene s;
  s.cloud = hand_cloud(20, 12, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    p = Eigen::Vector3f(0.01f * u, 0.01f * v, 2.0f + jitter(rng));
  });
  s.cloud.points[s.cloud.index(5, 4)] = tunnelmap::testing::no_normal();
  s.cloud.points[s.cloud.index(18, 9)] = tunnelmap::testing::no_normal();
  for (int k = 0; k < nplanes; ++k) {
    const float tilt_x = tilt(rng);  // drawn in order: argument order is the compiler's
    const float tilt_y = tilt(rng);
    const Eigen::Vector3f n = Eigen::Vector3f(tilt_x, tilt_y, -1.0f).normalized();
    s.planes.emplace_back(n.x(), n.y(), n.z(), -n.dot(Eigen::Vector3f(0.1f, 0.06f, 2.0f + jitter(rng))));
  }
  return s;
}

}  // namespace

TEST(BorderAssignment, MatchesAScalarReferenceForEveryCandidateCount) {
  const float eps = 0.015f;
  // Both kernels where the CPU has AVX2 (the SSE one is forced for the first pass).
  for (const bool sse : {true, false})
  for (int ncand = 1; ncand <= 9; ++ncand) {
    SCOPED_TRACE(ncand);
    force_sse_border_assignment(sse);
    SCOPED_TRACE(border_assignment_avx2_available() ? "AVX2" : "SSE");
    const Scene s = random_scene(40u + ncand, 9);
    // Candidates are ids 1..9 in a shuffled order, a subset of them offered.
    const std::int32_t order[9] = {7, 2, 9, 4, 1, 8, 3, 6, 5};
    std::vector<std::int32_t> labels(s.cloud.points.size(), -1);
    std::vector<PixelTally> tallies(9);
    // The cell [2, 15) x [1, 11): 13 pixels wide, so the SSE loop has a scalar tail.
    const int u0 = 2, v0 = 1, u1 = 15, v1 = 11;
    assign_to_nearest_plane(s.cloud, u0, v0, u1, v1, s.planes.data(), order, ncand, eps, labels.data(),
                            tallies.data());
    std::vector<PixelTally> expected(9);
    int assigned = 0;
    for (int v = v0; v < v1; ++v)
      for (int u = u0; u < u1; ++u) {
        const Eigen::Vector3f& p = s.cloud.points[s.cloud.index(u, v)];
        std::int32_t best = 0;
        float best_d = eps;
        for (int k = 0; k < ncand; ++k) {
          const Eigen::Vector4f& a = s.planes[order[k] - 1];
          const float d = std::abs(a.head<3>().dot(p) + a.w());
          if (d <= best_d) best_d = d, best = order[k];
        }
        ASSERT_EQ(labels[s.cloud.index(u, v)], best) << u << "," << v;
        if (best == 0) continue;
        ++assigned;
        PixelTally& t = expected[best - 1];
        ++t.count;
        t.sum_p += p.cast<double>();
        t.sum_z3 += std::pow(static_cast<double>(p.z()), 3);
        t.include_box(u, v, u, v);
      }
    EXPECT_GT(assigned, 0);
    EXPECT_EQ(labels[s.cloud.index(5, 4)], 0);  // invalid pixel
    EXPECT_EQ(labels[s.cloud.index(1, 1)], -1);  // outside the cell: untouched
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(tallies[i].count, expected[i].count) << "plane " << i + 1;
      EXPECT_NEAR((tallies[i].sum_p - expected[i].sum_p).norm(), 0.0, 1e-4);
      EXPECT_NEAR(tallies[i].sum_z3, expected[i].sum_z3, 1e-3);
      if (expected[i].count == 0) continue;
      EXPECT_EQ(tallies[i].u0, expected[i].u0);
      EXPECT_EQ(tallies[i].v0, expected[i].v0);
      EXPECT_EQ(tallies[i].u1, expected[i].u1);
      EXPECT_EQ(tallies[i].v1, expected[i].v1);
    }
  }
  force_sse_border_assignment(false);
}

TEST(BorderAssignment, TalliesAddUpOverCells) {
  force_sse_border_assignment(false);
  // Two cells side by side, one plane: the second call extends the first's box and sums.
  OrganizedCloud c = hand_cloud(16, 8, [&](int u, int v, Eigen::Vector3f& p, Eigen::Vector3f&) {
    p = Eigen::Vector3f(0.01f * u, 0.01f * v, u < 12 ? 1.0f : 1.5f);  // u >= 12: 0.5 m behind
  });
  const std::vector<Eigen::Vector4f> planes = {{0.0f, 0.0f, -1.0f, 1.0f}};  // z = 1
  const std::int32_t cand[1] = {1};
  std::vector<std::int32_t> labels(c.points.size(), -1);
  std::vector<PixelTally> t(1);
  assign_to_nearest_plane(c, 0, 0, 8, 8, planes.data(), cand, 1, 0.015f, labels.data(), t.data());
  assign_to_nearest_plane(c, 8, 0, 16, 8, planes.data(), cand, 1, 0.015f, labels.data(), t.data());
  EXPECT_EQ(t[0].count, 12 * 8);
  EXPECT_EQ(t[0].u0, 0);
  EXPECT_EQ(t[0].u1, 11);
  EXPECT_EQ(t[0].v0, 0);
  EXPECT_EQ(t[0].v1, 7);
  EXPECT_NEAR(t[0].sum_z3, 96.0, 1e-4);
  EXPECT_NEAR(t[0].sum_p.z(), 96.0, 1e-4);
  EXPECT_EQ(labels[c.index(13, 3)], 0);
}
