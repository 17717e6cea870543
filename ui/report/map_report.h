#pragma once
// The inspection report of a station map, as `map --report` and the GUI's File > Export
// inspection report write it: the PDF with the map's 3D image, drawn from the sectioned map
// PLY by tunnelmap-render in a child process.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

// `input`: the dataset as the user named it; `params`: the parameter values used. `map_ply`:
// the sectioned map PLY when one was just written (else one is written to a temporary
// folder). Without a renderer the report says why it has no image. InputError naming the PDF
// when it cannot be written; nothing is left behind. `notes`: the mapping's (MappingNotes::all()).
void write_map_report(const std::string& pdf_path, const std::string& input, const StationMap& map,
                      const nlohmann::json& params, const std::vector<std::string>& notes,
                      const std::string& map_ply = "");

}  // namespace tunnelmap
