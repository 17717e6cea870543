#pragma once
// The shown frame: the parameter dock (method and parameters), the frames-and-results dock
// (timeline, table, plot), the pipeline re-runs a parameter change asks for, the linked frame
// navigation, and the mesh layer that follows the shown frame's pose. Live frames and fused
// scenes reach the views through it too.
#include <QObject>
#include <QTimer>
#include <functional>
#include <memory>

#include "ui/mesh_opener.h"
#include "ui/mesh_overlay.h"
#include "ui/pipeline_runner.h"

class QActionGroup;
class QComboBox;
class QDockWidget;
class QMenu;

namespace tunnelmap::ui {

class ResultsPanel;
class TimelineWidget;
struct WindowContext;

class FrameController : public QObject {
  Q_OBJECT
 public:
  explicit FrameController(WindowContext& ctx);

  QDockWidget* parameters_dock() const { return params_dock_; }
  QDockWidget* results_dock() const { return results_dock_; }
  TimelineWidget* timeline() const { return timeline_; }
  ResultsPanel* results() const { return results_; }
  void add_method_menu(QMenu* processing);
  void build_navigation(QWidget* views);  // frame keys over the views and the results dock

  // A new input: its frames on the timeline and table, frame 0 requested next.
  void show_input();
  void reload_input();  // the same input read again (new intrinsics): every stage re-runs
  // Shows frame `index` (0-based) on the timeline, results table, plot and 3D view at once;
  // false if out of range. Every one of them calls this when clicked.
  bool select_frame(int index);
  bool step_frame(int delta);  // select_frame(shown + delta), clamped to the input
  void request_run(bool immediate);
  int frame_index() const { return frame_index_; }
  int frame_count() const;  // of the open input (0: none)
  void set_method(Method method);
  Method method() const { return method_; }
  void update_plot_reference();  // ground truth of the dataset, else the design

  // The shown state (tests and --screenshot read it).
  const scene::ProcessedFrame* current() const { return current_.get(); }
  std::shared_ptr<const scene::ProcessedFrame> current_frame() const { return current_; }
  const RunOutcome& last_outcome() const { return last_; }
  int shown_runs() const { return shown_runs_; }
  double last_show_ms() const { return last_show_ms_; }  // GUI thread: swap inputs + render

  // A live camera frame: into the views with `status` as the status line.
  void show_live_outcome(const RunOutcome& outcome, const QString& status);
  void start_live();  // the camera's frames are not the open input's: table and timeline cleared
  void stop_live();
  std::function<bool()> live_running = [] { return false; };  // frames come from the camera

  // A triangle mesh PLY in the world frame, read and cut into pieces on the background job
  // (progress and Cancel in the status bar) and shown when ready: meshOpened tells the outcome.
  // False, and nothing started, while another job runs.
  bool open_mesh(const QString& path);
  MeshOverlay& mesh() { return mesh_; }

 signals:
  void frameShown();  // a pipeline result reached the views
  void meshOpened(bool ok);  // open_mesh finished: shown, or failed or cancelled

 private:
  void build_parameters_dock();
  void build_results_dock();
  void on_run_finished(const RunOutcome& outcome);
  void show_views(const RunOutcome& outcome);
  void record_result(const RunOutcome& outcome);

  WindowContext& ctx_;
  QDockWidget* params_dock_ = nullptr;
  QDockWidget* results_dock_ = nullptr;
  QWidget* results_box_ = nullptr;
  QComboBox* method_combo_ = nullptr;
  QActionGroup* method_actions_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  ResultsPanel* results_ = nullptr;
  Method method_ = Method::Pgc;
  PipelineRunner runner_;
  QTimer debounce_;
  MeshOverlay mesh_;
  MeshOpener opener_;
  int frame_index_ = 0;
  bool reset_camera_ = true;
  std::shared_ptr<const scene::ProcessedFrame> current_;
  RunOutcome last_;
  int shown_runs_ = 0;
  double last_show_ms_ = 0.0;
};

}  // namespace tunnelmap::ui
