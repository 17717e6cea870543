#pragma once
// A hand-built StationMap with realistic numbers for the report tests: 24 m of tunnel in three
// sections (design 0.82 x 1.30 m, 10 mm tolerance), a local bulge and a low roof out of
// tolerance, stations inferred from context and design, six poses of which one needs a rescan.
#include "core/mapping/station_map.h"

namespace tunnelmap::test {

StationMap make_report_station_map();

}  // namespace tunnelmap::test
