#include "ui/export_controller.h"

#include <QAction>
#include <QImage>
#include <QMainWindow>
#include <QMenu>
#include <QPixmap>
#include <functional>

#include "core/export/map_ply.h"
#include "core/export/planes_ply.h"
#include "core/report/results_csv.h"
#include "core/report/results_json.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "ui/file_dialogs.h"
#include "ui/frame_controller.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/review_controller.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

ExportController::ExportController(WindowContext& ctx, FrameController* frames, ReviewController* review)
    : QObject(ctx.window), ctx_(ctx), frames_(frames), review_(review) {}

void ExportController::add_actions(QMenu* file) {
  using Writer = std::function<bool(const QString&)>;
  const auto add = [this, file](const QString& text, const QString& title, const QString& filter,
                                const QString& suffix, const char* name, Writer write) {
    file->addAction(text, this, [=] {
      const QString p = ctx_.dialogs->ask_save_path(title, filter, suffix);
      if (!p.isEmpty()) write(p);
    })->setObjectName(name);
  };
  const QString ply = tr("PLY (*.ply)"), csv = tr("CSV (*.csv)");
  ReviewController* r = review_;
  add(tr("Export &map PLY…"), tr("Export map PLY"), ply, "ply", "exportMapPly",
      [this](const QString& p) { return export_map_ply(p); });
  add(tr("Export &station CSV…"), tr("Export station CSV"), csv, "csv", "exportStationCsv",
      [r](const QString& p) { return r->export_station_csv(p); });
  add(tr("Export &diaphragms CSV…"), tr("Export diaphragms CSV"), csv, "csv", "exportDiaphragmsCsv",
      [r](const QString& p) { return r->export_diaphragms_csv(p); });
  add(tr("Export inspection &report PDF…"), tr("Export inspection report"), tr("PDF (*.pdf)"), "pdf", "exportReport",
      [r](const QString& p) { return r->export_report(p); });
  add(tr("Export &planes PLY…"), tr("Export planes PLY"), ply, "ply", "exportPlanesPly",
      [this](const QString& p) { return export_planes_ply(p); });
  add(tr("Export results &JSON…"), tr("Export results JSON"), tr("JSON (*.json)"), "json", "exportResultsJson",
      [this](const QString& p) { return export_results_json(p); });
  add(tr("Export results &CSV…"), tr("Export results CSV"), csv, "csv", "exportResultsCsv",
      [this](const QString& p) { return export_results_csv(p); });
  add(tr("Save &screenshot…"), tr("Save screenshot"), tr("PNG (*.png)"), "png", "saveScreenshot",
      [this](const QString& p) { return save_screenshot(p); });
}

bool ExportController::write(const QString& path, const std::function<void()>& writer) {
  return ctx_.status->run_or_show_error(writer, tr("Wrote %1").arg(path));
}

bool ExportController::export_map_ply(const QString& path) {
  if (review_->mapped_tunnel()) return review_->export_sectioned_map_ply(path);
  const scene::ProcessedFrame* shown = frames_->current();
  if (!shown) return ctx_.status->show_error(tr("%1: nothing to export (open an input first)").arg(path)), false;
  return write(path, [&] {
    const Eigen::Isometry3d to_world = shown->frame.pose ? *shown->frame.pose : Eigen::Isometry3d::Identity();
    write_map_ply(path.toStdString(), shown->result.map, ctx_.params->parameters().to_json(), to_world);
  });
}

bool ExportController::export_planes_ply(const QString& path) {
  const scene::ProcessedFrame* shown = frames_->current();
  if (!shown) return ctx_.status->show_error(tr("%1: nothing to export (open an input first)").arg(path)), false;
  return write(path, [&] {
    write_planes_ply(path.toStdString(), shown->result.cloud, shown->result.planes, shown->result.map.plane_classes);
  });
}

// The table's rows as `detect --json` writes them, with each row's parameter set.
bool ExportController::export_results_json(const QString& path) {
  const ResultsPanel* results = frames_->results();
  return write(path, [&] {
    write_detection_json(path.toStdString(),
                         results_document(results->records(), ctx_.params->parameters(), ctx_.input_path.toStdString(),
                                          ctx_.dataset(), [results](int set) { return results->parameter_set(set); }));
  });
}

bool ExportController::export_results_csv(const QString& path) {
  return write(path, [&] {
    write_detection_csv(path.toStdString(), results_document(frames_->results()->records(), Parameters(), {}, nullptr));
  });
}

bool ExportController::save_screenshot(const QString& path) {
  const QImage image = ctx_.window->grab().toImage();
  return write(path, [&] {
    write_path_atomically(path.toStdString(), [&](const std::string& tmp) {
      if (!image.save(QString::fromStdString(tmp), "PNG")) throw InputError(path.toStdString(), "cannot write PNG");
    });
  });
}

}  // namespace tunnelmap::ui
