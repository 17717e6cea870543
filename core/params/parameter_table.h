#pragma once
// The single source of truth for every tunable value of the pipeline. The GUI builds its
// sliders from it, the CLI its --set, the JSON presets their keys. Defaults are the paper's.
// Each row is declared beside its module (core/*/*_options.h, see parameter_key.h); this table
// lists them in the order `params`, presets and the GUI show.
#include <string>
#include <vector>

#include "core/params/parameter_key.h"

namespace tunnelmap {

const std::vector<ParameterSpec>& parameter_table();
const ParameterSpec* find_parameter(const std::string& key);  // nullptr when unknown
// Cross-field rules of all modules (e.g. cloud.min_range_m < cloud.max_range_m).
const std::vector<ParameterRule>& parameter_rules();

}  // namespace tunnelmap
