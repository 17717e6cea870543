#pragma once
// The one writer of dataset.json ("tunnelmap-dataset/1", docs/dataset-format.md): its common
// keys, its encodings of poses, vectors and frame file names, and the file itself. The dataset
// copy, the recording extraction and the simulator write through it, so the reader
// (core/io/dataset.h) meets one format whoever wrote the folder.
#include <Eigen/Geometry>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/frame/intrinsics.h"

namespace tunnelmap {

// A pose as 16 numbers, row by row (camera to world), the bottom row exactly 0 0 0 1.
nlohmann::json dataset_pose_json(const Eigen::Isometry3d& pose);

// [x, y, z].
nlohmann::json dataset_vector_json(const Eigen::Vector3d& v);

// "000042" + extension (".png"): frame files sort in frame order.
std::string dataset_frame_file(std::size_t index, const std::string& extension);

// format, intrinsics, depth_scale (image units per metre), up and frames; callers add their
// own keys ("ground_truth", "recording", "simulator", "robot").
nlohmann::json dataset_document(const Intrinsics& K, double depth_scale, const Eigen::Vector3d& up,
                                nlohmann::json frames);

// folder/dataset.json, written whole or not at all (InputError naming the file).
void write_dataset_json(const std::filesystem::path& folder, const nlohmann::json& document);

}  // namespace tunnelmap
