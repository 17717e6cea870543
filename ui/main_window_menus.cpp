// MainWindow's menus and their actions (object names are what tests trigger).
#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QUndoStack>

#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open…"), this, [this] {
    const QString path = ask_open_path(tr("Open depth PNG, PCD, recording or dataset.json"),
                                       tr("Inputs (*.png *.pcd *.oni *.bag *.mcap *.db3 *.json);;All files (*)"));
    if (!path.isEmpty()) open_interactively(path);
  }, QKeySequence::Open)->setObjectName("open");
  file->addAction(tr("Open r&ecording…"), this, [this] {
    const QString path = ask_open_path(tr("Open robot recording (ROS bag)"),
                                       tr("Recordings (*.bag *.mcap *.db3 metadata.yaml);;All files (*)"));
    // A rosbag2 folder is chosen by its metadata.yaml.
    if (!path.isEmpty()) open_interactively(QFileInfo(path).fileName() == "metadata.yaml" ? QFileInfo(path).path() : path);
  })->setObjectName("openRecording");
  file->addAction(tr("Open &folder…"), this, [this] {
    QSettings s;
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open dataset folder"),
                                                          s.value("files/lastFolder").toString());
    if (!dir.isEmpty()) open_interactively(dir);
  });
  file->addAction(tr("Open &mesh…"), this, [this] {
    const QString path = ask_open_path(tr("Open mesh PLY"), tr("PLY (*.ply)"));
    if (!path.isEmpty()) open_mesh(path);
  })->setObjectName("openMesh");
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
  build_session_actions(file);  // review sessions, Export 3D view, intrinsics (main_window_session.cpp)
  file->addSeparator();
  // Each export: a menu entry, a save dialog (title, filter, default suffix) and its writer.
  const auto add_export = [this, file](const QString& text, const QString& title, const QString& filter,
                                       const QString& suffix, const char* name, bool (MainWindow::*write)(const QString&)) {
    file->addAction(text, this, [=] {
      const QString p = ask_save_path(title, filter, suffix);
      if (!p.isEmpty()) (this->*write)(p);
    })->setObjectName(name);
  };
  const QString ply = tr("PLY (*.ply)"), csv = tr("CSV (*.csv)");
  add_export(tr("Export &map PLY…"), tr("Export map PLY"), ply, "ply", "exportMapPly", &MainWindow::export_map_ply);
  add_export(tr("Export &station CSV…"), tr("Export station CSV"), csv, "csv", "exportStationCsv",
             &MainWindow::export_station_csv);
  add_export(tr("Export &diaphragms CSV…"), tr("Export diaphragms CSV"), csv, "csv", "exportDiaphragmsCsv",
             &MainWindow::export_diaphragms_csv);
  add_export(tr("Export inspection &report PDF…"), tr("Export inspection report"), tr("PDF (*.pdf)"), "pdf",
             "exportReport", &MainWindow::export_report);
  add_export(tr("Export &planes PLY…"), tr("Export planes PLY"), ply, "ply", "exportPlanesPly",
             &MainWindow::export_planes_ply);
  add_export(tr("Export results &JSON…"), tr("Export results JSON"), tr("JSON (*.json)"), "json", "exportResultsJson",
             &MainWindow::export_results_json);
  add_export(tr("Export results &CSV…"), tr("Export results CSV"), csv, "csv", "exportResultsCsv",
             &MainWindow::export_results_csv);
  add_export(tr("Save &screenshot…"), tr("Save screenshot"), tr("PNG (*.png)"), "png", "saveScreenshot",
             &MainWindow::save_screenshot);
  file->addSeparator();
  file->addAction(tr("Process whole &sequence"), this, &MainWindow::process_sequence)
      ->setObjectName("processSequence");
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  // Edit: undo/redo of parameter changes (each completed edit, Reset all, a loaded preset).
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = params_->undo_stack()->createUndoAction(this, tr("&Undo"));
  undo->setObjectName("undo");
  undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
  edit->addAction(undo);
  QAction* redo = params_->undo_stack()->createRedoAction(this, tr("&Redo"));
  redo->setObjectName("redo");
  redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  edit->addAction(redo);

  QMenu* processing = menuBar()->addMenu(tr("&Processing"));
  QMenu* method_menu = processing->addMenu(tr("&Method"));
  method_actions_ = new QActionGroup(this);
  for (Method m : {Method::Pgc, Method::Ransac, Method::Qhull}) {
    QAction* a = method_menu->addAction(QString::fromUtf8(method_display_name(m)).replace("&", "&&"));
    a->setObjectName(QString("method_") + method_name(m));
    a->setCheckable(true);
    a->setChecked(m == method_);
    method_actions_->addAction(a);
    connect(a, &QAction::triggered, this, [this, m] { set_method(m); });
  }
  processing->addAction(tr("Process whole &sequence"), this, &MainWindow::process_sequence);
  processing->addAction(tr("&Fuse sequence"), this, &MainWindow::fuse_sequence)->setObjectName("fuseSequence");

  QMenu* device = menuBar()->addMenu(tr("&Device"));
  device->addAction(tr("&Refresh device list"), this, [this] { refresh_devices(); })->setObjectName("refreshDevices");
  devices_menu_ = device->addMenu(tr("&Devices"));
  device_actions_ = new QActionGroup(this);
  device->addAction(tr("&Start live view"), this, [this] { start_live_view(QString()); })->setObjectName("startLive");
  device->addAction(tr("Start live view on &URI…"), this, [this] {
    bool ok = false;
    const QString uri = QInputDialog::getText(this, tr("Live view"), tr("OpenNI2 device URI:"), QLineEdit::Normal,
                                              "tunnelmap-sim://lab", &ok);
    if (ok && !uri.isEmpty()) start_live_view(uri);
  });
  device->addAction(tr("S&top live view"), this, &MainWindow::stop_live_view)->setObjectName("stopLive");
  device->addSeparator();
  device->addAction(tr("&Record…"), this, [this] {
    const QString p = ask_save_path(tr("Record OpenNI2 .oni"), tr("OpenNI recording (*.oni)"), "oni");
    if (!p.isEmpty()) start_recording(p);
  })->setObjectName("record");
  device->addAction(tr("Stop r&ecording"), this, [this] { stop_recording(); })->setObjectName("stopRecording");
  update_device_actions();

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (scene::Layer layer : scene::all_layers()) {
    QAction* a = view->addAction(tr(scene::layer_title(layer)));
    a->setCheckable(true);
    a->setChecked(view3d_->scene().layer_visible(layer));
    connect(a, &QAction::toggled, this, [this, layer](bool on) { view3d_->set_layer_visible(layer, on); });
  }
  view->addSeparator();
  refined_action_ = view->addAction(tr("Refined &poses"));
  refined_action_->setObjectName("refinedPoses");
  refined_action_->setCheckable(true);
  refined_action_->setChecked(true);
  refined_action_->setEnabled(false);  // until a fusion with refined poses is shown
  refined_action_->setStatusTip(tr("Fused view: camera frusta, merged map and mesh at the refined poses (on) "
                                   "or at the forward-kinematics poses (off)"));
  connect(refined_action_, &QAction::toggled, this, &MainWindow::show_refined_poses);
  view->addSeparator();
  view->addAction(tr("Look &along the tunnel"), this, [this] { view3d_->apply_view(scene::ViewPreset::Along); }, QKeySequence("1"));
  view->addAction(tr("From the &side"), this, [this] { view3d_->apply_view(scene::ViewPreset::Side); }, QKeySequence("2"));
  view->addAction(tr("From &above"), this, [this] { view3d_->apply_view(scene::ViewPreset::Top); }, QKeySequence("3"));
  view->addAction(tr("&Reset camera"), this, [this] { view3d_->apply_view(scene::ViewPreset::Reset); }, QKeySequence("0"));
  build_review_docks(processing, view);  // cross-section, profile, measuring (main_window_review.cpp)
}

}  // namespace tunnelmap::ui
