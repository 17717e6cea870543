#pragma once
// The inspection window: 3D view + 2D depth view, parameter panel, timeline and results panel,
// File/Processing/Device/View menus, status bar. Every error becomes one message naming the
// file and the problem, in the status bar and the Messages dock (never a dialog); the
// previously open input and results stay. Implementation split by job: main_window.cpp (layout,
// input, re-runs, presets, mesh), main_window_menus.cpp, main_window_device.cpp (live OpenNI2),
// main_window_sequence.cpp, main_window_fusion.cpp, results_export.cpp (File-menu exports).
#include <QFuture>
#include <QMainWindow>
#include <QTimer>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/pipeline_runner.h"

namespace tunnelmap {
struct StationMap;
struct DatasetMapping;
}

class QAction;
class QActionGroup;
class QComboBox;
class QLabel;
class QMenu;
class QProgressBar;
class QDockWidget;
class QPushButton;
class QToolButton;

namespace tunnelmap::ui {

class CrossSectionPanel;
class MapSectionsPanel;
class DepthViewWidget;
class ProfilePlot;
class RecordingOpener;
struct ReviewMap;
class LiveView;
class MessageLog;
class ParameterPanel;
class ResultsPanel;
class TimelineWidget;
class View3DWidget;
struct FusedScene;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // All return false and show the error (status bar + Messages dock) on failure.
  bool open_input(const QString& path);  // recordings with the topics the CLI would choose
  // File > Open, Open recording, drag and drop, recent files: a recording is indexed, its
  // topics chosen in a dialog and its frames read on a worker, with progress and Cancel
  // (true: started; the input changes when it is done).
  bool open_interactively(const QString& path);
  RecordingOpener* recording_opener() const { return recordings_; }
  // Shows frame `index` (0-based) of the open input on the timeline, results table, plot and 3D
  // view at once; false if out of range. Every one of them calls this when clicked.
  bool select_frame(int index);
  bool step_frame(int delta);  // select_frame(shown + delta), clamped to the input
  int frame_index() const { return frame_index_; }
  TimelineWidget* timeline() const { return timeline_; }
  bool load_preset(const QString& path);  // its name is shown in the title and status bar
  QString preset_name() const { return preset_name_; }  // "defaults" until a preset is loaded
  bool save_preset(const QString& path);
  // After Processing > Map tunnel: the sectioned map with its plates (as `map --ply`);
  // otherwise the shown frame's tunnel.
  bool export_map_ply(const QString& path);
  // After Map tunnel, as `map --csv`, `--diaphragms-csv` and `--report` write them; an error
  // when the open input has not been mapped.
  bool export_station_csv(const QString& path);
  bool export_diaphragms_csv(const QString& path);
  bool export_report(const QString& path);
  bool export_planes_ply(const QString& path);
  bool export_results_json(const QString& path);
  bool export_results_csv(const QString& path);
  bool save_screenshot(const QString& path);  // grab of the whole window
  // A triangle mesh PLY (e.g. a fused mesh, world frame) shown in the RGB-D mesh layer, moved
  // into the camera frame of the shown frame when its pose is known.
  bool open_mesh(const QString& path);
  void process_sequence();                    // every frame, with progress and cancel
  // Detection method (PG&C or a paper baseline): re-runs the shown frame when it changes.
  void set_method(Method method);
  Method method() const { return method_; }
  QString status_text() const;

  // OpenNI2 devices (Device menu). All return false and show the error on failure.
  QStringList refresh_devices();                 // URIs of the connected devices
  bool start_live_view(const QString& uri);      // "" = the device chosen in Device > Devices
  void stop_live_view();
  bool start_recording(const QString& path);     // .oni, while the live view runs
  bool stop_recording();
  LiveView* live_view() const { return live_; }

  // Processing > Fuse sequence (posed datasets): TSDF mesh, merged map and one frustum per arm
  // pose, in the world frame, on a worker thread with progress and cancel.
  void fuse_sequence();
  // View > Refined poses (`refinedPoses`, enabled while a fused result whose poses were refined
  // is shown): on, the frusta and merged map at the refined poses the mesh was fused with; off,
  // at the forward-kinematics poses, and the mesh re-fused with them (once, on the worker).
  void show_refined_poses(bool refined);
  bool refined_poses_shown() const;
  // Camera centres of the frusta shown in the fused view (world frame), one per pose group.
  std::vector<Eigen::Vector3d> fused_frustum_centres() const;
  int fused_frusta() const { return fused_frusta_; }
  long long fused_triangles() const { return fused_triangles_; }
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
  MessageLog* messages() const { return messages_; }  // every error shown, oldest first
  bool suppress_dialogs = false;  // --exit runs and tests: never ask (confirmations take "no")

  // Dialog hooks, so tests can drive the real menu actions: the defaults show QFileDialog /
  // QMessageBox. A chooser returns the chosen path, or an empty string on cancel.
  using PathChooser = std::function<QString(const QString& title, const QString& folder, const QString& filter)>;
  PathChooser choose_open_path;  // File > Open…, Open mesh…, Load preset…
  PathChooser choose_save_path;  // exports, screenshot, Save preset…
  std::function<bool(const QString& path)> confirm_overwrite;  // true: replace the existing file

  // Review sessions and workflow (main_window_session.cpp, docs/gui.md "Review sessions")
  bool save_session(const QString& path);  // "tunnelmap-session/1" JSON, atomic
  bool open_session(const QString& path);  // all of it, or one error naming the file and no change
  bool export_view3d(const QString& path, int width, int height);  // the 3D scene alone, off-screen
  void use_intrinsics(const QString& input, const Intrinsics& K);  // for the next open of `input`
  bool set_intrinsics(const Intrinsics& K);  // re-reads the open PNG input; remembered per folder
  ReadOptions read_options_for(const QString& input) const;
  void build_session_actions(QMenu* file);
  void save_view_settings();     // layers, method, camera into QSettings
  void restore_view_settings();  // ... and back on the next start
  std::shared_ptr<struct SessionState> session_;

  // Review docks (main_window_review.cpp): the cross-section of the shown frame, the tunnel's
  // profile from Processing > Map tunnel, View > Measure in 3D.
  void map_tunnel();                    // posed datasets: the station map, on a worker thread
  bool map_running() const;
  // The frame that sees `station_m` best is shown, the cross-section cut there; false when no
  // frame sees it (or no map of this input).
  bool show_station(double station_m);
  CrossSectionPanel* cross_section() const { return cross_section_; }
  MapSectionsPanel* map_sections() const { return sections_; }
  ProfilePlot* profile() const { return profile_; }

 signals:
  void frameShown();  // a pipeline result reached the views
  void tunnelMapped(bool ok);
  void errorShown(const QString& message);
  void fusionFinished(bool ok);

 protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

 private:
  void build_menus();
  void apply_first_start_layout(QDockWidget* params, QDockWidget* results);
  void connect_recording_opener();
  // The station map of the open input (Map tunnel) and the parameters it was made with.
  struct MappedTunnel {
    const StationMap* map;
    nlohmann::json params;
  };
  std::optional<MappedTunnel> mapped_tunnel() const;
  bool write_map_export(const QString& path, const std::function<void(const MappedTunnel&)>& write);
  bool export_sectioned_map_ply(const QString& path);  // progress, Cancel and the result in the status bar
  void adopt_input(const QString& path, std::shared_ptr<const FrameSource> source);
  void build_navigation(QWidget* views, QWidget* results);  // keys over the views and results
  void update_plot_reference();  // ground truth of the dataset, else the design
  void clear_design(const QString& previous_input);
  void forget_review_state();
  void update_preset_status();   // title and status bar: input, preset, "(modified)"
  void offer_matching_preset();  // the dataset's tunnel kind has a preset: offer it
  void show_error(const QString& message);
  void on_run_finished(const RunOutcome& outcome);
  void request_run(bool immediate);
  void add_recent(const QString& path);
  void rebuild_recent_menu();
  QString ask_save_path(const QString& title, const QString& filter, const QString& suffix);
  QString ask_open_path(const QString& title, const QString& filter);
  void show_mesh();
  void show_views(const RunOutcome& outcome);  // swaps the outcome into the 3D and depth views
  void on_live_frame(const RunOutcome& outcome);
  void update_device_actions();
  void start_fusion(bool refine_poses);
  void show_fused(bool reset_camera);  // the fused result at the poses View > Refined poses chooses
  void leave_fused_view();
  void build_review_docks(QMenu* processing, QMenu* view);
  void build_sections_dock();
  void review_map_pending_station(int frame, std::optional<double> ahead_m);  // the cut's station once `frame` shows
  void review_frame_shown();  // the cross-section follows the shown frame
  void finish_map_tunnel(const std::shared_ptr<const FrameSource>& source, const DatasetMapping& result,
                         const nlohmann::json& params, const QString& error);

  View3DWidget* view3d_;
  DepthViewWidget* depth_view_;
  CrossSectionPanel* cross_section_ = nullptr;
  ProfilePlot* profile_ = nullptr;
  QDockWidget* cross_section_dock_ = nullptr;
  QDockWidget* profile_dock_ = nullptr;
  MapSectionsPanel* sections_ = nullptr;
  QDockWidget* sections_dock_ = nullptr;
  std::shared_ptr<ReviewMap> review_map_;
  int review_frame_ = -1;
  bool map_running_ = false;
  ParameterPanel* params_;
  ResultsPanel* results_;
  TimelineWidget* timeline_;
  QLabel* status_label_;
  QLabel* preset_label_;
  QPushButton* offer_preset_;
  QString preset_name_ = "defaults";
  Parameters preset_params_;  // the values the preset set (defaults: Parameters())
  MessageLog* messages_;
  QDockWidget* messages_dock_;
  QToolButton* messages_button_;
  QProgressBar* progress_;
  QPushButton* cancel_button_;
  QMenu* recent_menu_ = nullptr;
  QMenu* devices_menu_ = nullptr;
  QActionGroup* device_actions_ = nullptr;
  LiveView* live_ = nullptr;
  QComboBox* method_combo_ = nullptr;
  QActionGroup* method_actions_ = nullptr;
  Method method_ = Method::Pgc;

  PipelineRunner runner_;
  QTimer debounce_;
  std::shared_ptr<const FrameSource> source_;
  RecordingOpener* recordings_ = nullptr;
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
  int fused_frusta_ = 0;
  long long fused_triangles_ = 0;
  QFuture<void> sequence_future_;
  std::shared_ptr<FusedScene> fused_;  // the last fusion (refined poses when refinement ran)
  bool fused_shown_ = false;           // the 3D view shows it (not a single frame)
  bool given_mesh_ = false;            // fused_->given_geometry holds a mesh fused at given poses
  QAction* refined_action_ = nullptr;
};

}  // namespace tunnelmap::ui
