#pragma once
// The paper's Table 1 protocol on the simulated replicas: the lab rig (0.82 x 1.30 m, 3 robot
// poses) and the field box girder (0.84 x 1.20 m, 5 / 3 / 1.8 m from the manhole plate), 10
// frames per cell, fixed seeds; every method runs on the same rendered frames. Also runs
// users' datasets with ground truth (one cell per dataset).
#include <functional>
#include <string>
#include <vector>

#include "core/baselines/method_runner.h"
#include "core/evaluation/cell_result.h"
#include "core/sim/sim_config.h"
#include "core/util/build_paths.h"

namespace tunnelmap {

struct ProtocolOptions {
  std::vector<Method> methods{Method::Pgc, Method::Qhull, Method::Ransac};  // paper's column order
  int frames_per_cell = 10;
  int ransac_frames_per_cell = 10;  // R&L is slow by design: CI runs it on fewer frames
  unsigned seed = 1;
  BaselineOptions baselines;
  std::string presets_dir = std::string(TUNNELMAP_SOURCE_DIR) + "/resources/presets";
  std::vector<std::string> preset_overrides;  // KEY=VALUE, applied to every preset after loading
  std::function<void(const std::string&)> progress;  // one line per finished cell, may be empty
};

// PG&C (and the baselines' shared cloud range / template window) parameters of a preset.
// The options' preset_overrides are applied on top (ParameterError names a bad one).
Parameters preset_parameters(const ProtocolOptions& options, const std::string& name);

// Renders `frames_per_group` frames per pose group of `config` (config.frames is overridden)
// and runs every method on them. `cell_of(group)` names the cell of a pose group (groups with
// the same name are pooled). Each method keeps one TunnelContext per cell.
std::vector<CellResult> run_simulated(SimConfig config, const std::string& experiment,
                                      const std::function<std::string(int group)>& cell_of,
                                      double cell_value, const Parameters& params,
                                      const ProtocolOptions& options);

// Table 1: lab cells "Pose 1..3", then field cells "5m to plate", "3m to plate", "1.8m to plate".
std::vector<CellResult> run_table1(const ProtocolOptions& options);

// A dataset folder with ground truth (dataset.json "ground_truth" width/height; surface labels
// used when present). Every frame is one sample of the cell; R&L runs on the first
// ransac_frames_per_cell frames. `params` as for detect (defaults or a preset).
std::vector<CellResult> run_dataset(const std::string& dir, const Parameters& params,
                                    const ProtocolOptions& options);

}  // namespace tunnelmap
