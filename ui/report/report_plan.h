#pragma once
// The plan: the tunnel seen from above, station along x. Sections shaded alternately and
// labelled, joints (section changes) marked with their station, the width of every station as
// the outline, out-of-tolerance stations and the pose cameras marked, a station ruler in metres.
#include "core/mapping/station_map.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

// Left and right page margins of the plan's drawing area, shared by the plots so that their
// station axes line up with the plan's.
constexpr double kPlotLeftMm = 16.0;
constexpr double kPlotRightMm = 5.0;

void add_plan(Document& doc, const StationMap& map);

}  // namespace tunnelmap::report
