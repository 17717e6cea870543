#pragma once
// SimConfig <-> JSON (the "simulator" object of dataset.json), so a dataset can be
// regenerated bit for bit from its own description.
#include <nlohmann/json.hpp>
#include <string>

#include "core/sim/sim_config.h"

namespace tunnelmap {

nlohmann::json sim_config_to_json(const SimConfig& config);

// Starts from the preset named in j["preset"] (default "lab") and overrides every field
// present. Throws InputError(source, ...) for wrong types or out-of-range values.
SimConfig sim_config_from_json(const nlohmann::json& j, const std::string& source);

}  // namespace tunnelmap
