#pragma once
// Width or height against station: the design value and its tolerance band, every station as a
// point (measured filled, inferred from context or design hollow, out of tolerance red), the
// section values, section changes as dotted lines. Own y axis per dimension, in metres with
// at least 3 decimals so millimetre changes read directly.
#include "core/mapping/station_map.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

enum class Dimension { Width, Height };

void add_profile_plot(Document& doc, const StationMap& map, Dimension dim);

}  // namespace tunnelmap::report
