#pragma once
// The inspection window: 3D view + 2D depth view, parameter panel, timeline and results panel,
// File/View menus, status bar. Every file error becomes a message naming the file and the
// problem; the previously open input and results stay.
#include <QFuture>
#include <QMainWindow>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/pipeline_runner.h"

class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;

namespace tunnelmap::ui {

class DepthViewWidget;
class ParameterPanel;
class ResultsPanel;
class TimelineWidget;
class View3DWidget;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // All return false and show the error (status bar + message box) on failure.
  bool open_input(const QString& path);
  bool select_frame(int index);  // shows frame `index` of the open input; false if out of range
  bool load_preset(const QString& path);
  bool save_preset(const QString& path);
  bool export_map_ply(const QString& path);
  bool export_planes_ply(const QString& path);
  bool export_results_json(const QString& path);
  bool export_results_csv(const QString& path);
  bool save_screenshot(const QString& path);  // grab of the whole window
  // A triangle mesh PLY (e.g. a fused mesh, world frame) shown in the RGB-D mesh layer, moved
  // into the camera frame of the shown frame when its pose is known.
  bool open_mesh(const QString& path);
  void process_sequence();                    // every frame, with progress and cancel
  void cancel_sequence() { cancel_.store(true); }

  // For tests and --screenshot: the shown state.
  const scene::ProcessedFrame* current() const { return current_.get(); }
  int shown_runs() const { return shown_runs_; }
  const RunOutcome& last_outcome() const { return last_; }
  double last_show_ms() const { return last_show_ms_; }  // GUI thread: swap inputs + render
  QString last_error() const { return last_error_; }
  QString input_path() const { return input_path_; }
  ParameterPanel* parameter_panel() const { return params_; }
  View3DWidget* view3d() const { return view3d_; }
  ResultsPanel* results_panel() const { return results_; }
  bool suppress_dialogs = false;  // --exit runs and tests: errors only in status bar / stderr

  // Dialog hooks, so tests can drive the real menu actions: the defaults show QFileDialog /
  // QMessageBox. A chooser returns the chosen path, or an empty string on cancel.
  using PathChooser = std::function<QString(const QString& title, const QString& folder, const QString& filter)>;
  PathChooser choose_open_path;  // File > Open…, Open mesh…, Load preset…
  PathChooser choose_save_path;  // exports, screenshot, Save preset…
  std::function<bool(const QString& path)> confirm_overwrite;  // true: replace the existing file

 signals:
  void frameShown();  // a pipeline result reached the views
  void errorShown(const QString& message);

 protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

 private:
  void build_menus();
  void show_error(const QString& message);
  void on_run_finished(const RunOutcome& outcome);
  void request_run(bool immediate);
  void add_recent(const QString& path);
  void rebuild_recent_menu();
  QString ask_save_path(const QString& title, const QString& filter, const QString& suffix);
  QString ask_open_path(const QString& title, const QString& filter);
  void show_mesh();

  View3DWidget* view3d_;
  DepthViewWidget* depth_view_;
  ParameterPanel* params_;
  ResultsPanel* results_;
  TimelineWidget* timeline_;
  QLabel* status_label_;
  QProgressBar* progress_;
  QPushButton* cancel_button_;
  QMenu* recent_menu_ = nullptr;

  PipelineRunner runner_;
  QTimer debounce_;
  std::shared_ptr<const FrameSource> source_;
  QString input_path_;
  int frame_index_ = 0;
  bool reset_camera_ = true;
  std::shared_ptr<const scene::ProcessedFrame> current_;
  vtkSmartPointer<vtkPolyData> mesh_world_;  // loaded mesh PLY, as read
  int mesh_frame_ = -1;                      // frame whose pose placed the shown mesh
  RunOutcome last_;
  int shown_runs_ = 0;
  double last_show_ms_ = 0.0;
  QString last_error_;
  std::atomic<bool> cancel_{false};
  bool sequence_running_ = false;
  QFuture<void> sequence_future_;
};

}  // namespace tunnelmap::ui
