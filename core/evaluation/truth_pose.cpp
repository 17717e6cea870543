#include "core/evaluation/truth_pose.h"

namespace tunnelmap {

std::optional<Eigen::Isometry3d> truth_pose(const nlohmann::json& frame) {
  if (!frame.contains("pose_true")) return std::nullopt;
  const nlohmann::json& p = frame["pose_true"];
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) T.matrix()(r, c) = p[4 * r + c].get<double>();
  return T;
}

}  // namespace tunnelmap
