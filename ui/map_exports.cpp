// ReviewController, File-menu exports of the tunnel map after Processing > Map tunnel, with the
// same writers as `tunnelmap-cli map`: the sectioned map PLY (its plates and manholes), the
// station CSV, the diaphragms CSV and the PDF inspection report.
#include "core/export/map_ply.h"
#include "core/export/plate_mesh.h"
#include "core/mapping/station_map.h"
#include "core/report/girder_json.h"
#include "core/report/station_map_json.h"
#include "core/util/atomic_file.h"
#include "ui/report/map_report.h"
#include "ui/review_controller.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

bool ReviewController::write_map_export(const QString& path, const std::function<void(const MappedTunnel&)>& write) {
  const std::optional<MappedTunnel> mapped = mapped_tunnel();
  if (!mapped) {
    ctx_.status->show_error(tr("%1: nothing to export: map the tunnel first (Processing > Map tunnel)").arg(path));
    return false;
  }
  return ctx_.status->run_or_show_error([&] { write(*mapped); }, tr("Wrote %1").arg(path));
}

bool ReviewController::export_station_csv(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_file_atomically(path.toStdString(), [&](std::ostream& out) { out << station_map_csv(*m.map); });
  });
}

bool ReviewController::export_diaphragms_csv(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_file_atomically(path.toStdString(), [&](std::ostream& out) { out << diaphragms_csv(m.map->girder); });
  });
}

bool ReviewController::export_report(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_map_report(path.toStdString(), ctx_.input_path.toStdString(), *m.map, m.params, m.notes);
  });
}

bool ReviewController::export_sectioned_map_ply(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_sectioned_map_ply(path.toStdString(), m.map->section_maps, m.params, plate_outlines(*m.map));
  });
}

}  // namespace tunnelmap::ui
