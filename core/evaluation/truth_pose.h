#pragma once
// The simulator's true camera pose of a dataset frame ("pose_true", camera-to-world, row-major
// 4 x 4), which drifted datasets carry beside the drifted "pose".
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <optional>

namespace tunnelmap {

// Unknown when the frame has no "pose_true".
std::optional<Eigen::Isometry3d> truth_pose(const nlohmann::json& frame);

}  // namespace tunnelmap
