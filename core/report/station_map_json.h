#pragma once
// Machine-readable station map of `tunnelmap-cli map` (a contract users' scripts rely on:
// fields may be added, never renamed). See docs/cli.md#map.
#include <nlohmann/json.hpp>
#include <string>

#include "core/mapping/rescan_stretches.h"
#include "core/mapping/station_map.h"

namespace tunnelmap {

// {"station_m","width_m","height_m","width_source","height_source","frames","width_dev_mm",
//  "height_dev_mm","out_of_tolerance"}: values null where unknown.
nlohmann::json station_json(const Station& s);
// {"from_m","to_m","width_m","height_m","frames","joint","width_dev_mm","height_dev_mm"};
// "joint" (the one at from_m) is null for the first section, `first`.
nlohmann::json section_json(const Section& s, const StationMapOptions& o, bool first);
// A stretch to rescan: {"from_m","to_m","unmeasured":"width"|"height","joint_inside","reason"}.
nlohmann::json rescan_json(const RescanStretch& r);

// The whole document: {"tool","version","input","params","station_step_m","design",
// "tolerance_mm","frame","stations","sections","poses","rescan",(the girder's structure),"frames",
// "summary"}. `frames`: the
// per-frame detection objects of `detect --json` (may be empty).
nlohmann::json station_map_document(const StationMap& map, const nlohmann::json& params,
                                    const nlohmann::json& frames, const std::string& input);

// One row per station with the fields of station_json (header first).
std::string station_map_csv(const StationMap& map);

}  // namespace tunnelmap
