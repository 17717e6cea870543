#pragma once
// The single source of truth for every tunable value of the pipeline. The GUI builds its
// sliders from it, the CLI its --set, the JSON presets their keys. Defaults are the paper's.
#include <string>
#include <vector>

namespace tunnelmap {

// The first pipeline stage a parameter affects: changing it re-runs that stage and later ones.
// Fusion: multi-frame TSDF fusion (`fuse`), after the per-frame stages; changing it re-runs none.
// Map: the station map of the whole tunnel (`map`, `fuse --map`); changing it re-runs none.
enum class Stage { Cloud = 0, Normals = 1, Planes = 2, Tunnel = 3, Fusion = 4, Map = 5 };
const char* stage_name(Stage s);

struct ParameterSpec {
  std::string key;          // "grow.angle_deg"
  std::string unit;         // "deg", "mm", "m", "m2", "px", "points", "" (dimensionless)
  double default_value;
  double min;
  double max;
  double step;
  bool integer;             // whole numbers only
  Stage stage;
  std::string label;        // short human name for the GUI
  std::string description;  // one line, used as tooltip and in `params`
};

const std::vector<ParameterSpec>& parameter_table();
const ParameterSpec* find_parameter(const std::string& key);  // nullptr when unknown

}  // namespace tunnelmap
