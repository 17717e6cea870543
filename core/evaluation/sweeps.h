#pragma once
// Robustness sweeps on the simulated replicas: error and detection rate versus noise scale,
// dropout rate, camera roll, camera pitch, distance to the manhole plate and the zone (middle
// plate) thickness. Each sweep value pools all poses of the replica into one cell.
#include <string>
#include <vector>

#include "core/evaluation/protocol.h"

namespace tunnelmap {

struct SweepSpec {
  std::string name;             // "noise_scale", "dropout_scale", "roll_deg", ...
  std::string preset;           // replica: "lab" or "field"
  std::vector<double> values;
};

// The default sweeps (see docs/evaluation.md). `names` empty = all.
std::vector<SweepSpec> default_sweeps(const std::vector<std::string>& names = {});

// Applies one sweep value to a replica config (ParameterError for an unknown sweep name).
void apply_sweep_value(const std::string& name, double value, SimConfig& config);

// Runs the sweeps; results have experiment = sweep name, cell = "name=value", cell_value.
// options.frames_per_cell / ransac_frames_per_cell count frames per pose of the replica.
std::vector<CellResult> run_sweeps(const std::vector<SweepSpec>& sweeps, const ProtocolOptions& options);

}  // namespace tunnelmap
