#pragma once
// Dataset folders: a dataset.json ("tunnelmap-dataset/1") listing depth frames with optional
// colour, ground-truth surface labels, camera poses and arm joints, or a TUM RGB-D sequence
// (depth.txt, rgb.txt, groundtruth.txt) read into the same structure. See docs/dataset-format.md.
#include <Eigen/Geometry>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/frame/depth_frame.h"
#include "core/frame/intrinsics.h"
#include "core/io/read_options.h"

namespace tunnelmap {

constexpr const char* kDatasetFormat = "tunnelmap-dataset/1";

// Where a path came from in a list file (TUM sequences), so that load errors name that line.
struct ListOrigin {
  std::string file;
  int line = 0;
};

struct DatasetFrameRef {
  std::string depth_path, rgb_path, gt_path;  // resolved, inside the dataset folder; rgb/gt may be empty
  std::optional<Eigen::Isometry3d> pose;      // camera-to-world
  std::vector<double> joints;
  std::optional<Eigen::Vector3d> gravity;     // camera frame, unit: where things fall
  double timestamp_s = 0.0;
  nlohmann::json raw;                         // the frame's object as written (extra keys kept)
  std::optional<ListOrigin> depth_origin, rgb_origin;  // TUM lists; none for dataset.json
};

// Depth frames of a TUM sequence that found no colour image or no ground truth within the time
// limit: they are kept (without colour / without pose) and counted here.
struct UnmatchedFrames {
  std::size_t rgb = 0, pose = 0;
  std::vector<std::string> notes;  // one line per such frame
};

struct Dataset {
  std::string dir, json_path;
  Intrinsics intrinsics;
  double depth_scale = 1000.0;                 // depth PNG units per metre
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // world up, unit
  std::vector<DatasetFrameRef> frames;
  std::optional<double> gt_width_m, gt_height_m;
  nlohmann::json robot, ground_truth, raw;     // null when absent
  UnmatchedFrames unmatched;                   // TUM sequences only
  long long max_image_pixels = input_keys::max_image_pixels.default_value;  // from ReadOptions

  // Depth + rgb (if any; must match the size) + pose + joints, validated. InputError naming
  // dataset.json and the frame index on any problem.
  DepthFrame load_frame(std::size_t i) const;
  // Ground-truth surface label image (width*height), empty if the frame has none.
  std::vector<std::uint16_t> load_gt_surfaces(std::size_t i) const;
};

// Accepts the dataset folder or its dataset.json, or a TUM RGB-D sequence (a folder with
// depth.txt and no dataset.json, or its depth.txt). Validates the whole input (keys, types,
// poses, intrinsics, paths staying inside the folder, files existing); InputError on the first
// problem. `opt` reaches TUM sequences (intrinsics, depth scale, time limit) and sets the world
// up of both layouts when opt.world_up is given; a dataset.json keeps its own intrinsics and scale.
Dataset read_dataset(const std::string& dir_or_json_path);
Dataset read_dataset(const std::string& dir_or_json_path, const ReadOptions& opt);

}  // namespace tunnelmap
