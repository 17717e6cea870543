#pragma once
// Dataset folders: a dataset.json ("tunnelmap-dataset/1") listing depth frames with optional
// colour, ground-truth surface labels, camera poses and arm joints. See docs/dataset-format.md.
#include <Eigen/Geometry>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/frame/intrinsics.h"

namespace tunnelmap {

constexpr const char* kDatasetFormat = "tunnelmap-dataset/1";

struct DatasetFrameRef {
  std::string depth_path, rgb_path, gt_path;  // resolved, inside the dataset folder; rgb/gt may be empty
  std::optional<Eigen::Isometry3d> pose;      // camera-to-world
  std::vector<double> joints;
  double timestamp_s = 0.0;
  nlohmann::json raw;                         // the frame's object as written (extra keys kept)
};

struct Dataset {
  std::string dir, json_path;
  Intrinsics intrinsics;
  double depth_scale = 1000.0;                 // depth PNG units per metre
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // world up, unit
  std::vector<DatasetFrameRef> frames;
  std::optional<double> gt_width_m, gt_height_m;
  nlohmann::json robot, ground_truth, raw;     // null when absent

  // Depth + rgb (if any; must match the size) + pose + joints, validated. InputError naming
  // dataset.json and the frame index on any problem.
  DepthFrame load_frame(std::size_t i) const;
  // Ground-truth surface label image (width*height), empty if the frame has none.
  std::vector<std::uint16_t> load_gt_surfaces(std::size_t i) const;
};

// Accepts the dataset folder or its dataset.json. Validates the whole file (keys, types, poses,
// intrinsics, paths staying inside the folder, files existing); InputError on the first problem.
Dataset read_dataset(const std::string& dir_or_json_path);

}  // namespace tunnelmap
