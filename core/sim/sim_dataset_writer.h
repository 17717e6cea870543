#pragma once
// Writes a simulated dataset folder in the "tunnelmap-dataset/1" format read by core/io:
//   OUT/dataset.json, OUT/depth/NNNNNN.png (16-bit mm), OUT/rgb/NNNNNN.png (8-bit RGB),
//   OUT/gt/NNNNNN.png (16-bit surface ids). See docs/simulator.md.
#include <functional>
#include <string>

#include "core/sim/sim_config.h"

namespace tunnelmap {

// Called after each frame's images are written: (index, frame_count, depth path).
using SimProgress = std::function<void(int, int, const std::string&)>;

// Creates `out_dir` if needed. Refuses (InputError) a non-empty folder that is not already a
// tunnelmap dataset (or the remains of an interrupted write). Every file is written
// atomically; dataset.json is written last, so it only ever describes complete frames.
// Throws ParameterError for an invalid config.
void write_sim_dataset(const std::string& out_dir, const SimConfig& config);
void write_sim_dataset(const std::string& out_dir, const SimConfig& config,
                       const SimProgress& progress);

}  // namespace tunnelmap
