// build_cloud: the AVX2 row step (chosen at run time) gives the SSE step's points bit for bit,
// NaN where the depth is missing or out of range, on any width.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "core/normals/cloud_builder.h"
#include "core/normals/cloud_builder_avx2.h"

using namespace tunnelmap;

TEST(CloudBuilder, Avx2RowsMatchTheSseOnesAndTheFormula) {
  if (!cloud_builder_avx2_available()) GTEST_SKIP() << "this CPU has no AVX2";
  DepthFrame frame;
  frame.width = 37, frame.height = 5;  // 4 vectors of 8 and a tail of 5 per row
  frame.intrinsics.fx = 570.3, frame.intrinsics.fy = 571.1, frame.intrinsics.cx = 18.5, frame.intrinsics.cy = 2.5;
  frame.depth_units_per_m = 5000.0;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> depth(0.0f, 40000.0f);  // 0-8 m: some beyond the 5 m range
  frame.depth.resize(37 * 5);
  for (float& d : frame.depth) d = std::round(depth(rng));
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  frame.depth[1] = 0.0f, frame.depth[9] = nan, frame.depth[17] = inf, frame.depth[20] = -3.0f;
  frame.depth[21] = 1000.0f;  // 0.2 m: nearer than the 0.3 m minimum
  CloudOptions options;
  OrganizedCloud sse, avx;
  force_sse_cloud_builder(true);
  build_cloud(frame, options, sse);
  force_sse_cloud_builder(false);
  build_cloud(frame, options, avx);
  ASSERT_EQ(avx.points.size(), frame.depth.size());
  EXPECT_EQ(std::memcmp(sse.points.data(), avx.points.data(), sse.points.size() * sizeof(avx.points[0])), 0);
  int valid = 0;
  for (int v = 0; v < 5; ++v)
    for (int u = 0; u < 37; ++u) {
      const Eigen::Vector3f& p = avx.points[avx.index(u, v)];
      const float z = frame.depth[v * 37 + u] / 5000.0f;
      if (!(z >= 0.3f && z <= 5.0f)) {
        EXPECT_TRUE(std::isnan(p.x()) && std::isnan(p.y()) && std::isnan(p.z())) << u << "," << v;
        continue;
      }
      ++valid;
      EXPECT_EQ(p.z(), z);
      EXPECT_NEAR(p.x(), (u - 18.5) / 570.3 * z, 1e-6);
      EXPECT_NEAR(p.y(), (v - 2.5) / 571.1 * z, 1e-6);
    }
  EXPECT_GT(valid, 80);
  EXPECT_TRUE(std::isnan(avx.points[1].z()) && std::isnan(avx.points[9].z()) && std::isnan(avx.points[17].z()));
  EXPECT_TRUE(std::isnan(avx.points[20].z()) && std::isnan(avx.points[21].z()));
}
