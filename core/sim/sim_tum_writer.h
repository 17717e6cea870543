#pragma once
// A simulated sequence in the TUM RGB-D layout (simulate --format tum): the dataset the
// simulator writes, converted by core/io/tum_writer. Kept: depth (at 5000 units per metre),
// colour, poses (groundtruth.txt), intrinsics, world up and the "ground_truth" object
// (tunnelmap.json). Not kept: the ground-truth surface label images, arm joints (their poses
// are), the simulator settings and per-frame extras (pose groups, distances to the manhole).
#include <functional>
#include <string>

#include "core/sim/sim_config.h"
#include "core/sim/sim_dataset_writer.h"

namespace tunnelmap {

// `out_dir`: new, empty, or a TUM sequence written by TunnelMap (replaced whole); InputError
// otherwise, before anything is simulated. `progress` as write_sim_dataset's, with the TUM
// depth paths; `note` gets one-line notes from the conversion (null = silent).
void write_sim_tum_sequence(const std::string& out_dir, const SimConfig& config,
                            const SimProgress& progress,
                            const std::function<void(const std::string&)>& note = {});

}  // namespace tunnelmap
