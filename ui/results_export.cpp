// File menu exports (map PLY, planes PLY, results JSON/CSV, screenshot) and the results files
// they write. All writes are atomic: a failed export leaves no partial file.
#include <QLabel>
#include <QPixmap>
#include <nlohmann/json.hpp>

#include "core/export/map_ply.h"
#include "core/export/planes_ply.h"
#include "core/report/results_csv.h"
#include "core/report/results_json.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/results_export.h"
#include "ui/results_panel.h"

namespace tunnelmap::ui {

void write_results_json(const std::string& path, const std::string& input,
                        const std::vector<FrameRecord>& records, const Parameters& params,
                        const Dataset* dataset, const std::function<std::optional<Parameters>(int)>& set_params) {
  write_detection_json(path, results_document(records, params, input, dataset, set_params));
}

void write_results_csv(const std::string& path, const std::vector<FrameRecord>& records) {
  write_detection_csv(path, results_document(records, Parameters(), {}, nullptr));
}

bool MainWindow::export_map_ply(const QString& path) {
  if (mapped_tunnel()) return export_sectioned_map_ply(path);
  if (!current_) return show_error(tr("%1: nothing to export (open an input first)").arg(path)), false;
  try {
    const Eigen::Isometry3d to_world = current_->frame.pose ? *current_->frame.pose : Eigen::Isometry3d::Identity();
    write_map_ply(path.toStdString(), current_->result.map, params_->parameters().to_json(), to_world);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  status_label_->setText(tr("Wrote %1").arg(path));
  return true;
}

bool MainWindow::export_planes_ply(const QString& path) {
  if (!current_) return show_error(tr("%1: nothing to export (open an input first)").arg(path)), false;
  try {
    write_planes_ply(path.toStdString(), current_->result.cloud, current_->result.planes,
                     current_->result.map.plane_classes);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  status_label_->setText(tr("Wrote %1").arg(path));
  return true;
}

bool MainWindow::export_results_json(const QString& path) {
  try {
    write_results_json(path.toStdString(), input_path_.toStdString(), results_->records(),
                       params_->parameters(), source_ ? source_->dataset() : nullptr,
                       [this](int set) { return results_->parameter_set(set); });
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

bool MainWindow::export_results_csv(const QString& path) {
  try {
    write_results_csv(path.toStdString(), results_->records());
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

bool MainWindow::save_screenshot(const QString& path) {
  const QImage image = grab().toImage();
  try {
    write_path_atomically(path.toStdString(), [&](const std::string& tmp) {
      if (!image.save(QString::fromStdString(tmp), "PNG"))
        throw InputError(path.toStdString(), "cannot write PNG");
    });
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

}  // namespace tunnelmap::ui
