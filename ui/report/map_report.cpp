#include "ui/report/map_report.h"

#include <unistd.h>

#include <ctime>
#include <filesystem>

#include "core/export/map_ply.h"
#include "core/export/plate_mesh.h"
#include "core/util/temp_registry.h"
#include "ui/report/inspection_report.h"
#include "ui/report/report_map_image.h"

namespace tunnelmap {

namespace {

std::string now_text() {
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&t));
  return buf;
}

}  // namespace

void write_map_report(const std::string& pdf_path, const std::string& input, const StationMap& map,
                      const nlohmann::json& params, const std::vector<std::string>& notes,
                      const std::string& map_ply) {
  InspectionReportInput in;
  in.notes = notes;
  in.input = input;
  in.created = now_text();
  in.params = params;
  in.map = &map;
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() / ("tunnelmap-report-" + std::to_string(getpid()));
  TempRegistry::create(tmp, [&] { std::filesystem::create_directories(tmp); });  // removed on SIGINT/SIGTERM too
  const std::string ply = map_ply.empty() ? (tmp / "map.ply").string() : map_ply;
  const std::string png = (tmp / "map.png").string();
  std::string why;
  try {
    if (!map.section_maps.empty()) {
      if (map_ply.empty()) write_sectioned_map_ply(ply, map.section_maps, params, plate_outlines(map));
      if (render_map_image(ply, png, why)) in.map_image_png = png;
    } else {
      why = "the map has no section";
    }
    in.map_image_note = why;
    write_inspection_report(pdf_path, in);
  } catch (...) {
    std::filesystem::remove_all(tmp);
    TempRegistry::remove(tmp);
    throw;
  }
  std::filesystem::remove_all(tmp);
  TempRegistry::remove(tmp);
}

}  // namespace tunnelmap
