// A dataset frame's true pose: "pose_true" read row-major, unknown without it.
#include "core/evaluation/truth_pose.h"

#include <gtest/gtest.h>

namespace tunnelmap {
namespace {

TEST(TruthPose, ReadsPoseTrueRowMajorAndIsUnknownWithoutIt) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(12.5, -0.4, 1.1);
  nlohmann::json pose = nlohmann::json::array();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) pose.push_back(T.matrix()(r, c));
  const auto read = truth_pose({{"pose", nlohmann::json::array()}, {"pose_true", pose}});
  ASSERT_TRUE(read.has_value());
  EXPECT_LT((read->matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_FALSE(truth_pose({{"pose", pose}}).has_value());
}

}  // namespace
}  // namespace tunnelmap
