#include <gtest/gtest.h>

#include <cmath>

#include "core/normals/cloud_builder.h"
#include "core/normals/integral_normals.h"
#include "core/util/sse_xyz.h"
#include "tests/support/synthetic_scene.h"

using namespace tunnelmap;
using namespace tunnelmap::test;

namespace {
double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

// Fraction of pixels (at least `margin` px away from any other plane or hole) whose normal is
// within `tol_deg` of the analytic one; also the worst such error.
struct NormalScore { double within = 0; double worst_deg = 0; int checked = 0; };

NormalScore score(const SyntheticFrame& s, const OrganizedCloud& cloud,
                  const std::vector<AnalyticPlane>& planes, int margin, double tol_deg) {
  NormalScore out;
  int ok = 0;
  const Eigen::Matrix3d Rt = s.frame.pose->linear().transpose();
  for (int v = margin; v < cloud.height - margin; ++v) {
    for (int u = margin; u < cloud.width - margin; ++u) {
      const int id = s.plane_id[cloud.index(u, v)];
      if (id < 0) continue;
      bool interior = true;
      for (int dv = -margin; dv <= margin && interior; dv += margin)
        for (int du = -margin; du <= margin && interior; du += margin)
          interior = s.plane_id[cloud.index(u + du, v + dv)] == id;
      if (!interior) continue;
      const Eigen::Vector3f& n = cloud.normals[cloud.index(u, v)];
      ++out.checked;
      if (n.x() != n.x()) continue;
      const double err = angle_deg(n.cast<double>(), Rt * planes[id].normal);
      out.worst_deg = std::max(out.worst_deg, err);
      if (err < tol_deg) ++ok;
    }
  }
  out.within = out.checked ? static_cast<double>(ok) / out.checked : 0.0;
  return out;
}
}  // namespace

TEST(IntegralNormals, TiltedPlaneNormalsAreExactAwayFromEdges) {
  // A plane 2 m away tilted 50 degrees: the normals face the camera and match the analytic one.
  const Eigen::Vector3d n = Eigen::Vector3d(0.0, std::sin(50 * M_PI / 180), -std::cos(50 * M_PI / 180));
  const std::vector<AnalyticPlane> planes = {{n, 2.0 * std::cos(50 * M_PI / 180)}};
  const auto s = render_planes(planes, Eigen::Isometry3d::Identity(), Eigen::Vector3d::Constant(-50),
                               Eigen::Vector3d::Constant(50));
  OrganizedCloud cloud;
  build_cloud(s.frame, CloudOptions{0.1, 20.0}, cloud);
  estimate_normals(NormalOptions{}, cloud);
  const NormalScore sc = score(s, cloud, planes, 12, 1.0);
  EXPECT_GT(sc.checked, 200000);
  EXPECT_GT(sc.within, 0.999);
  EXPECT_LT(sc.worst_deg, 1.0);
  // Orientation: towards the camera.
  const Eigen::Vector3f& c = cloud.normals[cloud.index(320, 240)];
  EXPECT_LT(c.dot(cloud.points[cloud.index(320, 240)]), 0.0f);
}

TEST(IntegralNormals, BoxRoomNormalsWithinOneDegreeAwayFromEdgesUnderNoise) {
  const auto planes = box_room({-1.5, -1.2, -1.0}, {1.5, 1.2, 1.4});
  const auto pose = look_at({-0.6, 0.4, 0.3}, {1.5, -1.2, -1.0});
  const auto s = render_planes(planes, pose, {-1.5, -1.2, -1.0}, {1.5, 1.2, 1.4}, 0.0005, 7);
  OrganizedCloud cloud;
  build_cloud(s.frame, CloudOptions{0.1, 20.0}, cloud);
  estimate_normals(NormalOptions{}, cloud);
  const NormalScore sc = score(s, cloud, planes, 15, 1.0);
  EXPECT_GT(sc.checked, 100000);
  EXPECT_GT(sc.within, 0.99) << "worst " << sc.worst_deg;
}

TEST(IntegralNormals, NoNormalsAcrossDepthDiscontinuities) {
  // Two parallel planes at 1 m and 2 m meeting at image column 320: pixels near the jump get
  // no normal instead of a smeared one.
  DepthFrame f;
  f.width = 640;
  f.height = 480;
  f.depth.assign(640 * 480, 0.0f);
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u) f.depth[v * 640 + u] = u < 320 ? 1000.0f : 2000.0f;
  OrganizedCloud cloud;
  build_cloud(f, CloudOptions{}, cloud);
  estimate_normals(NormalOptions{}, cloud);
  const auto& at_edge = cloud.normals[cloud.index(319, 240)];
  EXPECT_TRUE(at_edge.x() != at_edge.x());
  const auto& far = cloud.normals[cloud.index(100, 240)];
  ASSERT_TRUE(far.x() == far.x());
  EXPECT_NEAR(far.z(), -1.0f, 1e-4f);
}

TEST(CloudBuilder, RangeLimitsAndInvalidDepthBecomeNaN) {
  DepthFrame f;
  f.width = 4;
  f.height = 1;
  f.depth = {0.0f, 200.0f, 1000.0f, 7000.0f};
  OrganizedCloud cloud;
  build_cloud(f, CloudOptions{0.3, 5.0}, cloud);
  EXPECT_FALSE(OrganizedCloud::valid(cloud.points[0]));
  EXPECT_FALSE(OrganizedCloud::valid(cloud.points[1]));  // nearer than min range
  EXPECT_TRUE(OrganizedCloud::valid(cloud.points[2]));
  EXPECT_FALSE(OrganizedCloud::valid(cloud.points[3]));  // beyond max range
  EXPECT_FLOAT_EQ(cloud.points[2].z(), 1.0f);
  const float expected_x = static_cast<float>((2 - f.intrinsics.cx) / f.intrinsics.fx);
  EXPECT_FLOAT_EQ(cloud.points[2].x(), expected_x);
}

TEST(IntegralNormals, EveryColumnOfAnOddWidthFrameGetsItsNormal) {
  // The normals are computed four pixels at a time: a width that is not a multiple of four
  // (37) exercises the row tails, and the frame's last pixel, whose store must not overrun.
  Intrinsics K;
  K.width = 37, K.height = 29, K.fx = K.fy = 40.0, K.cx = 18.0, K.cy = 14.0;
  DepthFrame f = DepthFrame::blank_mm(K);
  // A plane tilted about the image's vertical axis: z = 1.5 + 0.4 x.
  for (int v = 0; v < K.height; ++v)
    for (int u = 0; u < K.width; ++u) {
      const double ray_x = (u - K.cx) / K.fx;
      f.depth[static_cast<std::size_t>(v) * K.width + u] = static_cast<float>(1000.0 * 1.5 / (1.0 - 0.4 * ray_x));
    }
  OrganizedCloud cloud;
  build_cloud(f, CloudOptions{0.1, 20.0}, cloud);
  estimate_normals(NormalOptions{}, cloud);
  ASSERT_EQ(cloud.normals.size(), 37u * 29u);
  const Eigen::Vector3d expected = Eigen::Vector3d(0.4, 0.0, -1.0).normalized();  // facing the camera
  int with_normal = 0;
  double worst = 0;
  for (const Eigen::Vector3f& n : cloud.normals) {
    if (n.x() != n.x()) continue;
    ++with_normal;
    worst = std::max(worst, angle_deg(n.cast<double>(), expected));
  }
  EXPECT_EQ(with_normal, 37 * 29);  // one-sided tangents reach every border pixel
  EXPECT_LT(worst, 0.05);
  const Eigen::Vector3f& last = cloud.normals.back();
  EXPECT_NEAR(last.cast<double>().dot(expected), 1.0, 1e-5);
}

TEST(SseXyz, FourTriplesSplitIntoCoordinatesAndBack) {
  float in[12], out[12];
  for (int i = 0; i < 12; ++i) in[i] = static_cast<float>(i + 1);  // x0 y0 z0 x1 ...
  __m128 x, y, z;
  load_xyz4(in, x, y, z);
  alignas(16) float xs[4], ys[4], zs[4];
  _mm_store_ps(xs, x), _mm_store_ps(ys, y), _mm_store_ps(zs, z);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(xs[i], in[3 * i]);
    EXPECT_EQ(ys[i], in[3 * i + 1]);
    EXPECT_EQ(zs[i], in[3 * i + 2]);
  }
  store_xyz4(out, x, y, z);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(out[i], in[i]) << i;
}
