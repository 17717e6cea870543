// MainWindow, File-menu exports of the tunnel map after Processing > Map tunnel, with the same
// writers as `tunnelmap-cli map`: the sectioned map PLY (its plates and manholes), the station
// CSV, the diaphragms CSV and the PDF inspection report.
#include <QLabel>

#include "core/export/map_ply.h"
#include "core/export/plate_mesh.h"
#include "core/report/girder_json.h"
#include "core/report/station_map_json.h"
#include "core/util/atomic_file.h"
#include "ui/main_window.h"
#include "ui/report/map_report.h"

namespace tunnelmap::ui {

namespace {
QString needs_map(const QString& path) {
  return QObject::tr("%1: nothing to export: map the tunnel first (Processing > Map tunnel)").arg(path);
}
}  // namespace

bool MainWindow::write_map_export(const QString& path, const std::function<void(const MappedTunnel&)>& write) {
  const std::optional<MappedTunnel> mapped = mapped_tunnel();
  if (!mapped) return show_error(needs_map(path)), false;
  try {
    write(*mapped);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  status_label_->setText(tr("Wrote %1").arg(path));
  return true;
}

bool MainWindow::export_station_csv(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_file_atomically(path.toStdString(), [&](std::ostream& out) { out << station_map_csv(*m.map); });
  });
}

bool MainWindow::export_diaphragms_csv(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_file_atomically(path.toStdString(), [&](std::ostream& out) { out << diaphragms_csv(m.map->girder); });
  });
}

bool MainWindow::export_report(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_map_report(path.toStdString(), input_path_.toStdString(), *m.map, m.params);
  });
}

bool MainWindow::export_sectioned_map_ply(const QString& path) {
  return write_map_export(path, [&](const MappedTunnel& m) {
    write_sectioned_map_ply(path.toStdString(), m.map->section_maps, m.params, plate_outlines(*m.map));
  });
}

}  // namespace tunnelmap::ui
