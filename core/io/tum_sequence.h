#pragma once
// TUM RGB-D sequences (vision.in.tum.de/data/datasets/rgbd-dataset/file_formats) as Datasets:
// depth.txt and rgb.txt ("timestamp path"), 16-bit depth PNGs at 5000 units per metre,
// an optional groundtruth.txt ("timestamp tx ty tz qx qy qz qw", camera-to-world) and our
// optional tunnelmap.json. See docs/dataset-format.md.
#include <string>

#include "core/io/dataset.h"
#include "core/io/read_options.h"

namespace tunnelmap {

constexpr double kTumDepthScale = 5000.0;  // depth PNG units per metre

// A folder holding depth.txt and no dataset.json (which would win), or a file named depth.txt.
bool is_tum_sequence(const std::string& path);

// Reads and validates the lists (line-numbered InputErrors), pairs each depth frame with the
// nearest colour image and interpolates its pose from the ground truth, both within
// opt.max_time_diff_s; unmatched frames are kept, counted in Dataset::unmatched and summed up
// in one opt.note line. Intrinsics: opt.intrinsics, else tunnelmap.json, else the freiburg
// camera named by the folder, else InputError. Depth scale 5000 unless opt.depth_scale_given.
// World up: opt.world_up, else tunnelmap.json, else +Z. Dataset::json_path is depth.txt.
Dataset read_tum_sequence(const std::string& path, const ReadOptions& opt);

}  // namespace tunnelmap
