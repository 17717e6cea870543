#pragma once
// The File menu's exports, each a menu entry, a save dialog (title, filter, default suffix) and
// its writer: the map PLY (after Map tunnel the sectioned map, else the shown frame's tunnel),
// the map's station and diaphragms CSV and PDF report, the shown frame's planes PLY, the
// results table as JSON and CSV (the documents `detect --json` and `--csv` write) and a
// screenshot of the window. Every write is atomic: a failed export leaves no partial file.
#include <QObject>

class QMenu;

namespace tunnelmap::ui {

class FrameController;
class ReviewController;
struct WindowContext;

class ExportController : public QObject {
  Q_OBJECT
 public:
  ExportController(WindowContext& ctx, FrameController* frames, ReviewController* review);

  void add_actions(QMenu* file);
  // All return false and show the error on failure.
  bool export_map_ply(const QString& path);
  bool export_planes_ply(const QString& path);
  bool export_results_json(const QString& path);
  bool export_results_csv(const QString& path);
  bool save_screenshot(const QString& path);  // grab of the whole window

 private:
  bool write(const QString& path, const std::function<void()>& writer);  // "Wrote …" or the error

  WindowContext& ctx_;
  FrameController* frames_;
  ReviewController* review_;
};

}  // namespace tunnelmap::ui
