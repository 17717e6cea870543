#pragma once
// The first part of the report: title, what was inspected and how (input, date, tool version,
// station step, design, tolerance), the summary of the map, the mapping's notes and the
// parameters used.
#include "ui/report/inspection_report.h"
#include "ui/report/report_document.h"

namespace tunnelmap::report {

void add_title_and_inputs(Document& doc, const InspectionReportInput& in);
void add_summary(Document& doc, const StationMap& map);
// The mapping's notes, a paragraph each, under their own heading; nothing when there are none.
void add_notes(Document& doc, const std::vector<std::string>& notes);
// All parameters as key = value pairs in two column pairs, small print.
void add_parameters(Document& doc, const nlohmann::json& params);

}  // namespace tunnelmap::report
