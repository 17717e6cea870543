#pragma once
// THE CSV form of a results document (`detect --csv`, the GUI's results export): one row per
// frame, for spreadsheets. Columns, in this order (a contract like the JSON's: columns may be
// added at the end, never renamed or moved):
//   index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,
//   total_ms,reason
// Numbers are written exactly as in the JSON document; an unknown value (width, ...) is an empty
// cell; text with a comma, quote or line break is quoted (RFC 4180). Read from the typed records,
// never from the JSON.
#include <string>

#include "core/report/results_json.h"

namespace tunnelmap {

std::string detection_csv(const DetectionDocument& document);

// Written atomically, like every output.
void write_detection_csv(const std::string& path, const DetectionDocument& document);

}  // namespace tunnelmap
