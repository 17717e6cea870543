#pragma once
// The report's tables of the structure the robot climbs through: the plates across the girder
// (where each diaphragm is, how many frames saw it, and its manhole: shape, size, clearance to
// the walls, or why none was measured) and the compartments between them.
#include "core/mapping/station_map.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

void add_diaphragms_table(Document& doc, const StationMap& map);
// The compartments between the plates: extent, size measured inside, which ends are plates.
void add_compartments_table(Document& doc, const StationMap& map);

}  // namespace tunnelmap::report
