#pragma once
// What the sequence writers (TUM layout, dataset layout) take besides the Dataset itself.
#include <Eigen/Geometry>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tunnelmap {

struct SequenceExport {
  // Camera-to-world per frame, resolved by the caller (explicit pose or the arm's forward
  // kinematics); empty = each frame's own "pose".
  std::vector<std::optional<Eigen::Isometry3d>> poses;
  // After each frame: (index, frame count, the depth image written).
  std::function<void(std::size_t, std::size_t, const std::string&)> progress;
  // One-line notes on what the export could not keep (null = silent).
  std::function<void(const std::string&)> note;
};

}  // namespace tunnelmap
