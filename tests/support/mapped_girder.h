#pragma once
// A simulated girder written to a temporary folder and mapped as `map` maps it with the box
// girder preset (resources/presets/field.json) and pose refinement on.
#include "core/evaluation/girder_scoring.h"
#include "core/mapping/station_map.h"
#include "core/sim/sim_config.h"

namespace tunnelmap::testing {

StationMap map_simulated_girder(const SimConfig& girder);

// The same map scored against the girder's truth as `evaluate --protocol girders` scores it.
GirderScore score_simulated_girder(const SimConfig& girder);

}  // namespace tunnelmap::testing
