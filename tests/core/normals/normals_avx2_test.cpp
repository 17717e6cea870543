// The AVX2 normal step (chosen at run time) gives the same normals, bit for bit, as the SSE
// step on every real frame, and the same NaN pattern (no normal at holes and edges).
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "core/io/depth_png.h"
#include "core/normals/normals_row_avx2.h"
#include "core/pipeline/pipeline.h"
#include "core/util/build_paths.h"

using namespace tunnelmap;

namespace {

OrganizedCloud cloud_of(const char* file, double fx, double fy, double cx, double cy) {
  ReadOptions opt;
  Intrinsics K;
  K.fx = fx, K.fy = fy, K.cx = cx, K.cy = cy;
  opt.intrinsics = K;
  const DepthFrame frame = read_depth_png(std::string(TUNNELMAP_TEST_DATA_DIR) + "/real-frames/" + file, opt);
  OrganizedCloud cloud;
  build_cloud(frame, cloud_options(Parameters()), cloud);
  return cloud;
}

void expect_same_normals(const char* file, double fx, double fy, double cx, double cy) {
  SCOPED_TRACE(file);
  OrganizedCloud sse = cloud_of(file, fx, fy, cx, cy), avx = sse;
  force_sse_normals(true);
  estimate_normals(normal_options(Parameters()), sse);
  force_sse_normals(false);
  estimate_normals(normal_options(Parameters()), avx);
  ASSERT_EQ(sse.normals.size(), avx.normals.size());
  std::size_t valid = 0, differing = 0;
  for (std::size_t i = 0; i < sse.normals.size(); ++i) {
    valid += sse.normals[i].x() == sse.normals[i].x();
    differing += std::memcmp(sse.normals[i].data(), avx.normals[i].data(), 3 * sizeof(float)) != 0;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(valid, sse.normals.size() / 4);  // the frames have normals to compare
}

}  // namespace

TEST(NormalsAvx2, SameNormalsAsSse) {
  if (!normals_avx2_available()) GTEST_SKIP() << "this CPU has no AVX2";
  expect_same_normals("cape_tunnel_depth.png", 575.927, 576.408, 315.150, 230.586);
  expect_same_normals("pcl_office_depth.png", 525, 525, 320, 240);
  expect_same_normals("rtabmap_lab_depth_17.png", 525, 525, 319.5, 239.5);
}
