#pragma once
// Writes a Dataset (e.g. read from a TUM sequence) as a "tunnelmap-dataset/1" folder:
// dataset.json, depth/NNNNNN.png copied unchanged (depth_scale kept), rgb/ and gt/ copied.
#include <string>

#include "core/io/dataset.h"
#include "core/io/sequence_export.h"

namespace tunnelmap {

// Frames get "depth", "rgb", "gt_surfaces" (when present), "pose" (ex.poses, else the frame's
// own) and "timestamp"; arm joints are not written (their poses are). Intrinsics, depth_scale,
// up and "ground_truth" are kept. The folder appears whole or not at all (StagedFolder);
// frames are loaded and validated first (InputError as Dataset::load_frame).
void write_dataset_folder(const Dataset& ds, const std::string& out_dir, const SequenceExport& ex);

}  // namespace tunnelmap
