#pragma once
// Writes a dataset whose frames carry other camera poses (e.g. refined against the tunnel
// map): the same dataset.json with each frame's "pose" replaced, and the frames' images
// hard-linked (copied where links are impossible) into the new folder. Readers take a frame's
// explicit "pose" before its "joints", so every command uses the new poses.
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/io/dataset.h"

namespace tunnelmap {

// `out_dir` must not exist or be empty. InputError naming it on failure; a failed write
// removes what it created.
void write_dataset_with_poses(const Dataset& dataset, const std::vector<Eigen::Isometry3d>& poses,
                              const std::string& out_dir);

}  // namespace tunnelmap
