#pragma once
// The report's table of the plates across the girder: where each diaphragm is, how many frames
// saw it, and its manhole (shape, size, clearance to the walls), or why none was measured.
#include "core/mapping/station_map.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

void add_diaphragms_table(Document& doc, const StationMap& map);

}  // namespace tunnelmap::report
