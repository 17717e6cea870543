#pragma once
// The girder's structure in `map --json` ("centreline", "diaphragms", "compartments") and the
// diaphragm CSV of `map --diaphragms-csv`. Unknown values are null, each null manhole with its
// reason. See docs/cli.md#map.
#include <nlohmann/json.hpp>
#include <string>

#include "core/mapping/girder_structure.h"

namespace tunnelmap {

// Adds "centreline", "diaphragms" and "compartments" to `doc`.
void add_girder_json(const GirderStructure& g, nlohmann::json& doc);

// One row per diaphragm: station, normal, frames, manhole centre, size, shape, clearances.
std::string diaphragms_csv(const GirderStructure& g);

}  // namespace tunnelmap
