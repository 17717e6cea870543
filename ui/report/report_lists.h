#pragma once
// The tables of the report: sections, stations out of tolerance, poses and stretches to rescan. Each says
// "none" when it has no rows.
#include "core/mapping/station_map.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

void add_sections_table(Document& doc, const StationMap& map);
void add_out_of_tolerance_table(Document& doc, const StationMap& map);
void add_rescan_table(Document& doc, const StationMap& map);
// Stretches whose width or height no frame measured (core/mapping/rescan_stretches.h).
void add_rescan_stretches_table(Document& doc, const StationMap& map);

}  // namespace tunnelmap::report
