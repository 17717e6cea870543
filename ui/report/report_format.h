#pragma once
// How the report prints numbers, sources and lists: metres with 3 decimals (millimetres), signed
// deviations in mm, frame lists as ranges.
#include <QString>
#include <optional>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap::report {

QString fixed(double v, int decimals);               // "0.820"; "-" for NaN
QString metres(double v);                            // "0.820" (3 decimals)
QString signed_mm(const std::optional<double>& mm);  // "+3.2", "-0.4"; "-" when empty
QString source_label(DimensionSource s);             // "measured", "context", "design", "unseen"
QString frame_list(const std::vector<int>& frames);  // "3-5, 9, 12-14"
QString design_text(const StationMapOptions& o);     // "0.820 x 1.300 m (W x H)" or "none"

// |deviation| beyond the tolerance (the map's own rule, per dimension).
bool beyond_tolerance(const std::optional<double>& dev_mm, double tolerance_mm);

// Deviation of `value_m` from an optional design value, in mm.
std::optional<double> deviation_mm(double value_m, const std::optional<double>& design_m);

}  // namespace tunnelmap::report
