#pragma once
// The rendered 3D image of the map, scaled to fit the page, or the note why there is none.
#include <string>

#include "ui/report/report_document.h"

namespace tunnelmap::report {

void add_map_image(Document& doc, const std::string& png_path, const std::string& note);

}  // namespace tunnelmap::report
