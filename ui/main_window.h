#pragma once
// The inspection window: the 3D and 2D views in the middle, and controllers that each own their
// docks, actions and state (docs/architecture.md, "The GUI's controllers"):
//   FrameController     parameters dock, frames-and-results dock, re-runs, navigation, mesh layer
//   InputController     File > Open…, Open recording…, Open folder…, Open recent, drag and drop
//   PresetController    presets, the title and the "(modified)" mark, the design per input
//   SequenceController  Process whole sequence
//   ReviewController    Map tunnel, profile, Sections and Cross-section docks, measuring, map exports
//   FusionController    Fuse sequence, View > Refined poses
//   DeviceController    the Device menu: OpenNI2 devices, live view, recording
//   IntrinsicsController, SessionController  intrinsics dock, review sessions, view settings
//   ExportController    the File menu's exports
// The window wires them (what a new input or the live camera clears, in order) and offers the
// calls the command line and the tests drive. Every error is one line in the status bar and
// the Messages dock (never a dialog); the input and results that were open stay.
#include <QMainWindow>
#include <memory>

#include "ui/background_job.h"
#include "ui/device_controller.h"
#include "ui/export_controller.h"
#include "ui/file_dialogs.h"
#include "ui/frame_controller.h"
#include "ui/fusion_controller.h"
#include "ui/input_controller.h"
#include "ui/intrinsics_controller.h"
#include "ui/preset_controller.h"
#include "ui/review_controller.h"
#include "ui/sequence_controller.h"
#include "ui/session_controller.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

class QMenu;

namespace tunnelmap::ui {

class CrossSectionPanel;
class MapSectionsPanel;
class MessageLog;
class ParameterPanel;
class ProfilePlot;
class ResultsPanel;
class TimelineWidget;
class View3DWidget;

class MainWindow : public QMainWindow {
  Q_OBJECT
  WindowStatus* status_;                  // before the dialog hooks below, which refer into
  std::unique_ptr<FileDialogs> dialogs_;  // the dialogs

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // The controllers, for everything the shortcuts below do not cover.
  FrameController* frames() const { return frames_; }
  InputController* inputs() const { return inputs_; }
  PresetController* presets() const { return presets_; }
  ReviewController* review() const { return review_; }
  FusionController* fusion() const { return fusion_; }
  DeviceController* devices() const { return devices_; }
  SessionController* sessions() const { return sessions_; }
  ExportController* exports() const { return exports_; }

  // Dialog hooks (FileDialogs), so tests and batch runs drive the real menu actions.
  FileDialogs::PathChooser& choose_open_path;
  FileDialogs::PathChooser& choose_save_path;
  std::function<bool(const QString& path)>& confirm_overwrite;
  bool& suppress_dialogs;

  // Input and frames (InputController, FrameController).
  bool open_input(const QString& path) { return inputs_->open_input(path); }
  bool open_interactively(const QString& path) { return inputs_->open_interactively(path); }
  RecordingOpener* recording_opener() const { return inputs_->recording_opener(); }
  QString input_path() const { return ctx_.input_path; }
  bool select_frame(int index) { return frames_->select_frame(index); }
  bool step_frame(int delta) { return frames_->step_frame(delta); }
  int frame_index() const { return frames_->frame_index(); }
  void set_method(Method method) { frames_->set_method(method); }
  Method method() const { return frames_->method(); }
  // Starts opening the mesh on the background job (false: another job runs); meshOpened tells.
  bool open_mesh(const QString& path) { return frames_->open_mesh(path); }
  const scene::ProcessedFrame* current() const { return frames_->current(); }
  int shown_runs() const { return frames_->shown_runs(); }
  const RunOutcome& last_outcome() const { return frames_->last_outcome(); }
  double last_show_ms() const { return frames_->last_show_ms(); }
  TimelineWidget* timeline() const { return frames_->timeline(); }
  ResultsPanel* results_panel() const { return frames_->results(); }
  ParameterPanel* parameter_panel() const { return ctx_.params; }
  View3DWidget* view3d() const { return ctx_.view3d; }
  QString status_text() const { return status_->text(); }
  QString last_error() const { return status_->last_error(); }
  MessageLog* messages() const { return status_->messages(); }

  // Presets, sequence, exports.
  bool load_preset(const QString& path) { return presets_->load_preset(path); }
  bool save_preset(const QString& path) { return presets_->save_preset(path); }
  QString preset_name() const { return presets_->preset_name(); }
  void process_sequence() { sequence_->process_sequence(); }
  void cancel_sequence() { job_.cancel(); }
  bool export_map_ply(const QString& path) { return exports_->export_map_ply(path); }
  bool export_station_csv(const QString& path) { return review_->export_station_csv(path); }
  bool export_diaphragms_csv(const QString& path) { return review_->export_diaphragms_csv(path); }
  bool export_report(const QString& path) { return review_->export_report(path); }
  bool export_planes_ply(const QString& path) { return exports_->export_planes_ply(path); }
  bool export_results_json(const QString& path) { return exports_->export_results_json(path); }
  bool export_results_csv(const QString& path) { return exports_->export_results_csv(path); }
  bool save_screenshot(const QString& path) { return exports_->save_screenshot(path); }

  // Review (ReviewController) and fusion (FusionController).
  void map_tunnel() { review_->map_tunnel(); }
  bool map_running() const { return review_->map_running(); }
  bool show_station(double station_m, QString* why_not = nullptr) { return review_->show_station(station_m, why_not); }
  CrossSectionPanel* cross_section() const { return review_->cross_section(); }
  MapSectionsPanel* map_sections() const { return review_->map_sections(); }
  ProfilePlot* profile() const { return review_->profile(); }
  void fuse_sequence() { fusion_->fuse_sequence(); }
  void show_refined_poses(bool refined) { fusion_->show_refined_poses(refined); }
  bool refined_poses_shown() const { return fusion_->refined_poses_shown(); }
  std::vector<Eigen::Vector3d> fused_frustum_centres() const { return fusion_->fused_frustum_centres(); }
  int fused_frusta() const { return fusion_->fused_frusta(); }
  long long fused_triangles() const { return fusion_->fused_triangles(); }

  // Devices (DeviceController).
  QStringList refresh_devices() { return devices_->refresh_devices(); }
  bool start_live_view(const QString& uri) { return devices_->start_live_view(uri); }
  void stop_live_view() { devices_->stop_live_view(); }
  bool start_recording(const QString& path) { return devices_->start_recording(path); }
  bool stop_recording() { return devices_->stop_recording(); }
  LiveView* live_view() const { return devices_->live_view(); }

  // Sessions and intrinsics (SessionController, IntrinsicsController).
  bool save_session(const QString& path) { return sessions_->save_session(path); }
  bool open_session(const QString& path) { return sessions_->open_session(path); }
  bool export_view3d(const QString& path, int width, int height) { return sessions_->export_view3d(path, width, height); }
  void use_intrinsics(const QString& input, const Intrinsics& K) { intrinsics_->use_intrinsics(input, K); }
  bool set_intrinsics(const Intrinsics& K) { return intrinsics_->set_intrinsics(K); }

 signals:
  void frameShown();  // a pipeline result reached the views
  void meshOpened(bool ok);  // open_mesh or File > Open mesh finished (false: error or cancelled)
  void tunnelMapped(bool ok);
  void errorShown(const QString& message);
  void fusionFinished(bool ok);

 protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

 private:
  QWidget* build_views();
  void create_controllers();
  void connect_input_changes();
  void build_menus();
  void add_view_actions(QMenu* view);
  void restore_settings();
  void apply_first_start_layout();

  BackgroundJob job_;
  WindowContext ctx_;
  FrameController* frames_ = nullptr;
  InputController* inputs_ = nullptr;
  PresetController* presets_ = nullptr;
  SequenceController* sequence_ = nullptr;
  ReviewController* review_ = nullptr;
  FusionController* fusion_ = nullptr;
  DeviceController* devices_ = nullptr;
  IntrinsicsController* intrinsics_ = nullptr;
  SessionController* sessions_ = nullptr;
  ExportController* exports_ = nullptr;
};

}  // namespace tunnelmap::ui
