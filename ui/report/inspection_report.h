#pragma once
// The inspection report: a PDF an engineer can file, written with Qt's PDF writer from a
// StationMap (input, date and parameters; a plan of the tunnel with its sections; width and
// height against station with the design and its tolerance band; the sections table; the
// out-of-tolerance stations; the poses to rescan; a rendered image of the map), with the notes
// the mapping made (the lines `map` prints: poses nothing checks, an IMU noisier than weighed).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/mapping/station_map.h"

namespace tunnelmap {

struct InspectionReportInput {
  std::string input;          // the dataset as the user named it
  std::string created;        // date and time of the run, as printed
  nlohmann::json params;      // parameter values used ({"key": value, ...})
  const StationMap* map = nullptr;
  std::string map_image_png;  // rendered 3D image of the map; empty: the report says why not
  std::string map_image_note; // why there is no image (when map_image_png is empty)
  std::vector<std::string> notes;  // MappingNotes::all(), as the CLI prints them
};

// Written atomically (temporary file, then rename); InputError naming the file on failure.
// Needs no display: a QGuiApplication on the "offscreen" platform is created when none exists.
void write_inspection_report(const std::string& pdf_path, const InspectionReportInput& in);

}  // namespace tunnelmap
