#pragma once
// THE CSV form of a results document (`detect --csv`, the GUI's results export): one row per
// frame, for spreadsheets. Columns, in this order (a contract like the JSON's: columns may be
// added at the end, never renamed or moved):
//   index,source,method,detected,status,width_m,height_m,width_source,height_source,planes,
//   total_ms,reason
// Numbers are written exactly as in the JSON document; a null (unknown width, ...) is an empty
// cell; text with a comma, quote or line break is quoted (RFC 4180).
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace tunnelmap {

// `document` as detection_document() builds it; a frame's own "method" (the GUI's rows can
// differ) wins over the document's.
std::string detection_csv(const nlohmann::json& document);

// Written atomically, like every output.
void write_detection_csv(const std::string& path, const nlohmann::json& document);

}  // namespace tunnelmap
