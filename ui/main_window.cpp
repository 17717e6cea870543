#include "ui/main_window.h"

#include <QActionGroup>
#include <QApplication>
#include <QComboBox>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStatusBar>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include "core/export/map_ply.h"
#include "core/export/planes_ply.h"
#include "core/io/ply_mesh_reader.h"
#include "core/util/atomic_file.h"
#include "core/util/error.h"
#include "sensors/openni/device_list.h"
#include "ui/depth_view_widget.h"
#include "ui/fused_scene.h"
#include "ui/live_view.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/timeline_widget.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

namespace {

// "width 0.820 m, height 1.300 m", "partial: width 0.820 m, height unknown", or the status.
QString map_summary(const tunnelmap::TunnelMap& m) {
  if (!m.detected) return QString::fromStdString(m.status);
  const auto dim = [](bool known, double v) {
    return known ? QObject::tr("%1 m").arg(v, 0, 'f', 3) : QObject::tr("unknown");
  };
  const QString dims = QObject::tr("width %1, height %2").arg(dim(m.has_width(), m.width_m), dim(m.has_height(), m.height_m));
  return m.status == "partial" ? QObject::tr("partial (%1): %2").arg(QString::fromStdString(m.reason), dims) : dims;
}
// "Pose 1: 0.64°, 6.3 mm" next to the pose's frustum; "Pose 1" when it has no correction.
QString pose_label(const FusedPoseGroup& p) {
  if (!p.corrected) return QObject::tr("Pose %1").arg(p.group);
  return QObject::tr("Pose %1: %2°, %3 mm")
      .arg(p.group)
      .arg(p.correction.rotation_deg, 0, 'f', 2)
      .arg(p.correction.translation_mm, 0, 'f', 1);
}

// The results panel's line for a pose: verdict, then its correction and the directions
// nothing constrained (kept at their forward-kinematics value).
QString pose_line(const FusedPoseGroup& p, bool refined) {
  QString line = QObject::tr("Pose %1 (frames %2–%3): %4")
                     .arg(p.group)
                     .arg(p.frames.empty() ? -1 : p.frames.front())
                     .arg(p.frames.empty() ? -1 : p.frames.back())
                     .arg(QString::fromStdString(p.message));
  if (!refined) return line;
  if (!p.corrected) return line + QObject::tr(" — not refined");
  line += QObject::tr(" — refined by %1°, %2 mm").arg(p.correction.rotation_deg, 0, 'f', 2).arg(p.correction.translation_mm, 0, 'f', 1);
  QStringList free;
  for (const auto& d : p.correction.degenerate) free << QString::fromStdString(d);
  line += free.isEmpty() ? QObject::tr("; all directions constrained")
                         : QObject::tr("; not constrained: %1").arg(free.join(", "));
  return line;
}

// "poses refined: largest 0.64°, 7.3 mm" (largest rotation and largest translation).
QString refinement_summary(const FusedScene& f) {
  if (!f.refined) return QObject::tr("poses not refined (no detection to align with)");
  double deg = 0.0, mm = 0.0;
  for (const auto& p : f.groups)
    if (p.corrected) {
      deg = std::max(deg, p.correction.rotation_deg);
      mm = std::max(mm, p.correction.translation_mm);
    }
  return QObject::tr("poses refined: largest %1°, %2 mm").arg(deg, 0, 'f', 2).arg(mm, 0, 'f', 1);
}

constexpr int kMaxRecent = 8;
constexpr int kDebounceMs = 60;  // while a slider is dragged; a release runs at once
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle("TunnelMap");
  setAcceptDrops(true);
  view3d_ = new View3DWidget(this);
  depth_view_ = new DepthViewWidget(this);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(view3d_);
  split->addWidget(depth_view_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  setCentralWidget(split);

  params_ = new ParameterPanel(this);
  params_->setMinimumWidth(450);  // label + slider + value + reset per row
  // Method selector above the parameters (same choice as Processing > Method).
  auto* params_box = new QWidget(this);
  auto* params_layout = new QVBoxLayout(params_box);
  params_layout->setContentsMargins(0, 0, 0, 0);
  auto* method_row = new QHBoxLayout;
  method_row->addWidget(new QLabel(tr("Method:"), params_box));
  method_combo_ = new QComboBox(params_box);
  method_combo_->setObjectName("methodCombo");
  for (Method m : {Method::Pgc, Method::Ransac, Method::Qhull})
    method_combo_->addItem(QString::fromUtf8(method_display_name(m)), static_cast<int>(m));
  method_row->addWidget(method_combo_, 1);
  params_layout->addLayout(method_row);
  params_layout->addWidget(params_, 1);
  connect(method_combo_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
    set_method(static_cast<Method>(method_combo_->itemData(i).toInt()));
  });
  auto* params_dock = new QDockWidget(tr("Parameters"), this);
  params_dock->setObjectName("parametersDock");
  params_dock->setWidget(params_box);
  addDockWidget(Qt::LeftDockWidgetArea, params_dock);

  auto* bottom = new QWidget(this);
  timeline_ = new TimelineWidget(bottom);
  results_ = new ResultsPanel(bottom);
  auto* bottom_layout = new QVBoxLayout(bottom);
  bottom_layout->setContentsMargins(0, 0, 0, 0);
  bottom_layout->addWidget(timeline_);
  bottom_layout->addWidget(results_, 1);
  auto* results_dock = new QDockWidget(tr("Frames and results"), this);
  results_dock->setObjectName("resultsDock");
  results_dock->setWidget(bottom);
  addDockWidget(Qt::BottomDockWidgetArea, results_dock);
  // First-run layout (a saved layout replaces it): most of the height for the views.
  resizeDocks({results_dock}, {230}, Qt::Vertical);

  status_label_ = new QLabel(tr("Ready"), this);
  progress_ = new QProgressBar(this);
  progress_->setMaximumWidth(200);
  progress_->hide();
  cancel_button_ = new QPushButton(tr("Cancel"), this);
  cancel_button_->hide();
  statusBar()->addWidget(status_label_, 1);
  statusBar()->addPermanentWidget(progress_);
  statusBar()->addPermanentWidget(cancel_button_);
  connect(cancel_button_, &QPushButton::clicked, this, &MainWindow::cancel_sequence);

  choose_open_path = [this](const QString& title, const QString& folder, const QString& filter) {
    return QFileDialog::getOpenFileName(this, title, folder, filter);
  };
  choose_save_path = [this](const QString& title, const QString& folder, const QString& filter) {
    // Overwriting is asked by confirm_overwrite (after the suffix is added), not twice.
    return QFileDialog::getSaveFileName(this, title, folder, filter, nullptr,
                                        QFileDialog::DontConfirmOverwrite);
  };
  confirm_overwrite = [this](const QString& path) {
    return QMessageBox::question(this, tr("Replace file?"),
                                 tr("%1 already exists. Replace it?").arg(path),
                                 QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
  };

  debounce_.setSingleShot(true);
  debounce_.setInterval(kDebounceMs);
  connect(&debounce_, &QTimer::timeout, this, [this] { request_run(true); });
  connect(params_, &ParameterPanel::parametersChanged, this, [this](bool immediate) {
    if (immediate) request_run(true);
    else debounce_.start();
  });
  connect(params_, &ParameterPanel::loadPresetRequested, this, [this] {
    const QString path = ask_open_path(tr("Load parameter preset"), tr("JSON (*.json)"));
    if (!path.isEmpty()) load_preset(path);
  });
  connect(params_, &ParameterPanel::savePresetRequested, this, [this] {
    const QString path = ask_save_path(tr("Save parameter preset"), tr("JSON (*.json)"), "json");
    if (!path.isEmpty()) save_preset(path);
  });
  connect(&runner_, &PipelineRunner::finished, this, &MainWindow::on_run_finished);
  connect(timeline_, &TimelineWidget::frameRequested, this, [this](int i) {
    frame_index_ = i;
    request_run(true);
  });
  connect(results_, &ResultsPanel::frameActivated, this, [this](int i) {
    timeline_->set_frame(i);
    frame_index_ = i;
    request_run(true);
  });
  connect(depth_view_, &DepthViewWidget::hovered, this,
          [this](const QString& t) { statusBar()->showMessage(t, 3000); });
  live_ = new LiveView(this);
  live_->parameters = [this] { return params_->parameters(); };
  live_->method = [this] { return method_; };
  connect(live_, &LiveView::frameReady, this, &MainWindow::on_live_frame);
  connect(live_, &LiveView::failed, this, [this](const QString& m) {
    update_device_actions();
    show_error(m);
  });
  build_menus();

  QSettings settings;
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  const QByteArray last = settings.value("params/last").toByteArray();
  if (!last.isEmpty()) {
    try {
      Parameters p;
      p.apply_json(nlohmann::json::parse(last.toStdString()), "settings");
      params_->set_parameters(p);
    } catch (const std::exception&) {
      // Stale settings from another version: defaults.
    }
  }
  if (geometry().width() < 400) resize(1400, 860);
}

MainWindow::~MainWindow() {
  live_->stop();
  cancel_.store(true);
  sequence_future_.waitForFinished();
}

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&Open…"), this, [this] {
    const QString path = ask_open_path(tr("Open depth PNG, PCD, OpenNI recording or dataset.json"),
                                       tr("Inputs (*.png *.pcd *.oni *.json);;All files (*)"));
    if (!path.isEmpty()) open_input(path);
  }, QKeySequence::Open)->setObjectName("open");
  file->addAction(tr("Open &folder…"), this, [this] {
    QSettings s;
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Open dataset folder"),
                                                          s.value("files/lastFolder").toString());
    if (!dir.isEmpty()) open_input(dir);
  });
  file->addAction(tr("Open &mesh…"), this, [this] {
    const QString path = ask_open_path(tr("Open mesh PLY"), tr("PLY (*.ply)"));
    if (!path.isEmpty()) open_mesh(path);
  })->setObjectName("openMesh");
  recent_menu_ = file->addMenu(tr("Open &recent"));
  rebuild_recent_menu();
  file->addSeparator();
  file->addAction(tr("Export &map PLY…"), this, [this] {
    const QString p = ask_save_path(tr("Export map PLY"), tr("PLY (*.ply)"), "ply");
    if (!p.isEmpty()) export_map_ply(p);
  })->setObjectName("exportMapPly");
  file->addAction(tr("Export &planes PLY…"), this, [this] {
    const QString p = ask_save_path(tr("Export planes PLY"), tr("PLY (*.ply)"), "ply");
    if (!p.isEmpty()) export_planes_ply(p);
  })->setObjectName("exportPlanesPly");
  file->addAction(tr("Export results &JSON…"), this, [this] {
    const QString p = ask_save_path(tr("Export results JSON"), tr("JSON (*.json)"), "json");
    if (!p.isEmpty()) export_results_json(p);
  })->setObjectName("exportResultsJson");
  file->addAction(tr("Export results &CSV…"), this, [this] {
    const QString p = ask_save_path(tr("Export results CSV"), tr("CSV (*.csv)"), "csv");
    if (!p.isEmpty()) export_results_csv(p);
  })->setObjectName("exportResultsCsv");
  file->addAction(tr("Save &screenshot…"), this, [this] {
    const QString p = ask_save_path(tr("Save screenshot"), tr("PNG (*.png)"), "png");
    if (!p.isEmpty()) save_screenshot(p);
  })->setObjectName("saveScreenshot");
  file->addSeparator();
  file->addAction(tr("Process whole &sequence"), this, &MainWindow::process_sequence)
      ->setObjectName("processSequence");
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

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
}

QString MainWindow::ask_save_path(const QString& title, const QString& filter, const QString& suffix) {
  QString path = choose_save_path(title, QSettings().value("files/lastFolder").toString(), filter);
  if (path.isEmpty()) return path;
  if (QFileInfo(path).suffix().isEmpty()) path += "." + suffix;
  if (QFileInfo::exists(path) && !confirm_overwrite(path)) {
    status_label_->setText(tr("Not written: %1 exists").arg(path));
    return {};
  }
  return path;
}

QString MainWindow::ask_open_path(const QString& title, const QString& filter) {
  return choose_open_path(title, QSettings().value("files/lastFolder").toString(), filter);
}

void MainWindow::show_error(const QString& message) {
  last_error_ = message;
  status_label_->setText(message);
  emit errorShown(message);
  if (suppress_dialogs) return;
  auto* box = new QMessageBox(QMessageBox::Warning, tr("TunnelMap"), message, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);  // never blocks the event loop (tests, running pipeline)
  box->show();
}

bool MainWindow::open_input(const QString& path) {
  std::shared_ptr<const FrameSource> source;
  try {
    source = tunnelmap::open_input(path.toStdString(), ReadOptions());
    if (source->size() == 0) throw InputError(path.toStdString(), "contains no frames");
    source->load(0);  // validate now: a bad file must not replace the current input
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  cancel_.store(true);
  if (live_->running()) stop_live_view();
  leave_fused_view();
  fused_.reset();  // a running compare fusion then finds nothing to attach to
  source_ = source;
  input_path_ = path;
  frame_index_ = 0;
  reset_camera_ = true;
  mesh_frame_ = -1;
  runner_.set_source(source_);
  results_->clear();
  timeline_->set_frame_count(static_cast<int>(source_->size()));
  setWindowTitle(tr("TunnelMap — %1").arg(QFileInfo(path).fileName()));
  add_recent(path);
  QSettings().setValue("files/lastFolder", QFileInfo(path).absolutePath());
  status_label_->setText(tr("Opened %1 (%2 frame(s))").arg(path).arg(source_->size()));
  request_run(true);
  return true;
}

bool MainWindow::select_frame(int index) {
  if (!source_ || index < 0 || index >= static_cast<int>(source_->size())) return false;
  if (index == frame_index_) return true;  // already shown or requested
  timeline_->set_frame(index);
  frame_index_ = index;
  request_run(true);
  return true;
}

void MainWindow::request_run(bool immediate) {
  if (!source_ || live_->running()) return;  // the live view picks up changes with its next frame
  if (!immediate) return debounce_.start();
  debounce_.stop();
  runner_.request(frame_index_, params_->parameters(), method_);
}

void MainWindow::show_views(const RunOutcome& outcome) {
  leave_fused_view();
  current_ = outcome.processed;
  QElapsedTimer shown;
  shown.start();
  if (outcome.geometry)
    view3d_->show_geometry(*outcome.geometry, reset_camera_);
  else
    view3d_->show_frame(*current_, reset_camera_);
  reset_camera_ = false;
  depth_view_->show_frame(current_, outcome.depth_image);
  last_show_ms_ = shown.nsecsElapsed() / 1e6;
  if (mesh_world_ && outcome.frame_index != mesh_frame_) show_mesh();  // another frame's pose
}

void MainWindow::on_live_frame(const RunOutcome& outcome) {
  last_ = outcome;
  if (!outcome.processed) return status_label_->setText(outcome.error);  // keep streaming
  show_views(outcome);
  const LiveStats st = live_->stats();
  const auto& m = current_->result.map;
  QString text = tr("Live %1 — %2 — %3 — %4 fps, latency %5 ms, %6 received, %7 dropped")
                     .arg(live_->uri())
                     .arg(QString::fromUtf8(method_display_name(outcome.method)))
                     .arg(map_summary(m))
                     .arg(st.fps, 0, 'f', 1)
                     .arg(st.latency_ms, 0, 'f', 0)
                     .arg(st.received)
                     .arg(st.dropped);
  if (live_->recording()) text += tr(" — recording (%1 frames)").arg(live_->frames_recorded());
  status_label_->setText(text);
  ++shown_runs_;
  emit frameShown();
}

QStringList MainWindow::refresh_devices() {
  QStringList uris;
  try {
    for (const auto& d : openni2::list_devices(false)) uris << QString::fromStdString(d.uri);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
  }
  const QString chosen = device_actions_->checkedAction() ? device_actions_->checkedAction()->data().toString() : QString();
  devices_menu_->clear();
  for (QAction* a : device_actions_->actions()) device_actions_->removeAction(a);
  for (const QString& uri : uris) {
    QAction* a = devices_menu_->addAction(uri);
    a->setData(uri);
    a->setCheckable(true);
    a->setChecked(uri == chosen || (chosen.isEmpty() && uri == uris.first()));
    device_actions_->addAction(a);
  }
  devices_menu_->setEnabled(!uris.isEmpty());
  status_label_->setText(uris.isEmpty() ? tr("No OpenNI2 device found") : tr("%1 device(s): %2").arg(uris.size()).arg(uris.join(", ")));
  return uris;
}

bool MainWindow::start_live_view(const QString& uri_in) {
  QString uri = uri_in;
  if (uri.isEmpty() && device_actions_->checkedAction()) uri = device_actions_->checkedAction()->data().toString();
  if (uri.isEmpty()) uri = "default";
  cancel_.store(true);  // a running sequence stops: the views show the device now
  try {
    live_->start(uri);
  } catch (const std::exception& e) {
    update_device_actions();
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  reset_camera_ = true;
  results_->clear();
  status_label_->setText(tr("Live %1: waiting for the first frame…").arg(uri));
  update_device_actions();
  return true;
}

void MainWindow::stop_live_view() {
  if (live_->recording()) stop_recording();
  live_->stop();
  update_device_actions();
  status_label_->setText(tr("Live view stopped"));
}

bool MainWindow::start_recording(const QString& path) {
  try {
    live_->start_recording(path);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_device_actions();
  status_label_->setText(tr("Recording to %1").arg(path));
  return true;
}

bool MainWindow::stop_recording() {
  if (!live_->recording()) return false;
  try {
    const int frames = live_->stop_recording();
    status_label_->setText(tr("Recorded about %1 frame(s)").arg(frames));
  } catch (const std::exception& e) {
    update_device_actions();
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  update_device_actions();
  return true;
}

void MainWindow::update_device_actions() {
  const bool live = live_->running(), rec = live_->recording();
  auto set = [this](const char* name, bool on) {
    if (auto* a = findChild<QAction*>(name)) a->setEnabled(on);
  };
  set("startLive", !live);
  set("stopLive", live);
  set("record", live && !rec);
  set("stopRecording", rec);
}

void MainWindow::set_method(Method method) {
  const int index = method_combo_->findData(static_cast<int>(method));
  if (method_combo_->currentIndex() != index) method_combo_->setCurrentIndex(index);  // re-enters
  for (QAction* a : method_actions_->actions())
    if (a->objectName() == QString("method_") + method_name(method)) a->setChecked(true);
  if (method == method_) return;
  method_ = method;
  request_run(true);
}

QString MainWindow::status_text() const { return status_label_->text(); }

void MainWindow::on_run_finished(const RunOutcome& outcome) {
  last_ = outcome;
  if (!outcome.processed) {
    show_error(outcome.error);
    return;
  }
  show_views(outcome);
  results_->set_record(FrameRecord::from(outcome.frame_index, current_->result, outcome.method));
  const auto& r = current_->result;
  auto total = r.timings_ms.find("total");
  status_label_->setText(
      tr("Frame %1/%2 — %8 — %3, %4 planes — pipeline %5 ms (from %6), update %7 ms")
          .arg(outcome.frame_index + 1)
          .arg(source_ ? source_->size() : 0)
          .arg(map_summary(r.map))
          .arg(r.planes.planes.size())
          .arg(total == r.timings_ms.end() ? 0.0 : total->second, 0, 'f', 1)
          .arg(stage_name(outcome.from))
          .arg(outcome.wall_ms, 0, 'f', 1)
          .arg(QString::fromUtf8(method_display_name(outcome.method))));
  ++shown_runs_;
  emit frameShown();
}

bool MainWindow::load_preset(const QString& path) {
  try {
    Parameters p = params_->parameters();
    p.load_json_file(path.toStdString());
    params_->set_parameters(p);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

bool MainWindow::save_preset(const QString& path) {
  try {
    params_->parameters().save_json_file(path.toStdString(), QFileInfo(path).baseName().toStdString());
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  return true;
}

namespace {

// Our strict PLY reader's mesh as VTK data (vtkPLYReader crashes on hostile files): points,
// triangles, per-vertex colours as the scalars ("RGB") and normals when the file has them.
vtkSmartPointer<vtkPolyData> to_poly_data(const PlyMesh& m) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(m.vertices.size()));
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), m.vertices[i].x(), m.vertices[i].y(), m.vertices[i].z());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->AllocateExact(static_cast<vtkIdType>(m.triangles.size()), static_cast<vtkIdType>(3 * m.triangles.size()));
  for (const auto& t : m.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (!m.colors.empty()) {
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    rgb->SetName("RGB");
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(static_cast<vtkIdType>(m.colors.size()));
    for (std::size_t i = 0; i < m.colors.size(); ++i)
      for (int k = 0; k < 3; ++k) rgb->SetTypedComponent(static_cast<vtkIdType>(i), k, m.colors[i][k]);
    poly->GetPointData()->SetScalars(rgb);
  }
  if (!m.normals.empty()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(m.normals.size()));
    for (std::size_t i = 0; i < m.normals.size(); ++i)
      for (int k = 0; k < 3; ++k) normals->SetTypedComponent(static_cast<vtkIdType>(i), k, m.normals[i][k]);
    poly->GetPointData()->SetNormals(normals);
  }
  return poly;
}

}  // namespace

bool MainWindow::open_mesh(const QString& path) {
  vtkSmartPointer<vtkPolyData> mesh;
  try {
    const std::string file = path.toStdString();
    const PlyMesh ply = read_ply_mesh(file);  // InputError(file, problem) on any bad input
    if (ply.vertices.empty()) throw InputError(file, "PLY has no vertices");
    if (ply.triangles.empty()) throw InputError(file, "PLY has no faces (not a mesh)");
    mesh = to_poly_data(ply);
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  mesh_world_ = mesh;
  mesh_frame_ = -1;
  show_mesh();
  status_label_->setText(tr("Mesh %1: %2 vertices, %3 triangles")
                             .arg(path)
                             .arg(mesh->GetNumberOfPoints())
                             .arg(mesh->GetNumberOfPolys()));
  return true;
}

void MainWindow::show_mesh() {
  if (!mesh_world_) return view3d_->set_mesh(nullptr);
  // The scene is in the shown frame's camera frame; a posed frame maps world -> camera.
  const bool posed = current_ && current_->frame.pose;
  mesh_frame_ = current_ ? last_.frame_index : -1;
  if (!posed) return view3d_->set_mesh(mesh_world_);
  const Eigen::Isometry3d to_camera = current_->frame.pose->inverse();
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->ShallowCopy(mesh_world_);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(mesh_world_->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh_world_->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh_world_->GetPoint(i, p);
    const Eigen::Vector3d q = to_camera * Eigen::Vector3d(p[0], p[1], p[2]);
    points->SetPoint(i, q.data());
  }
  moved->SetPoints(points);
  moved->GetPointData()->SetNormals(nullptr);  // world-frame normals would light it wrongly
  view3d_->set_mesh(moved);
}

bool MainWindow::export_map_ply(const QString& path) {
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
                       params_->parameters().to_json());
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

void MainWindow::process_sequence() {
  if (!source_ || sequence_running_) return;
  sequence_running_ = true;
  cancel_.store(false);
  const int n = static_cast<int>(source_->size());
  progress_->setRange(0, n);
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
  auto source = source_;
  const Parameters params = params_->parameters();
  const Method method = method_;
  sequence_future_ = QtConcurrent::run([this, source, params, method, n] {
    TunnelContext context;
    for (int i = 0; i < n && !cancel_.load(); ++i) {
      FrameRecord rec;
      QString error;
      try {
        const auto pf = process_with_method(*source, static_cast<std::size_t>(i), method, params, &context);
        rec = FrameRecord::from(i, pf.result, method);
      } catch (const std::exception& e) {
        rec.index = i;
        rec.method = method;
        rec.status = "error";
        error = QString::fromStdString(e.what());
      }
      QMetaObject::invokeMethod(this, [this, rec, error, i] {
        results_->set_record(rec);
        progress_->setValue(i + 1);
        if (!error.isEmpty()) status_label_->setText(error);
      });
    }
    QMetaObject::invokeMethod(this, [this] {
      progress_->hide();
      cancel_button_->hide();
      sequence_running_ = false;
      status_label_->setText(results_->summary_text());
    });
  });
}

void MainWindow::fuse_sequence() { start_fusion(true); }

void MainWindow::start_fusion(bool refine_poses) {
  if (sequence_running_) return;
  const Dataset* ds = source_ ? source_->dataset() : nullptr;
  if (!ds) {
    show_error(tr("%1: Fuse sequence needs a posed dataset (dataset.json with poses or joints)")
                   .arg(input_path_.isEmpty() ? tr("no input") : input_path_));
    emit fusionFinished(false);
    return;
  }
  if (live_->running()) stop_live_view();
  sequence_running_ = true;
  cancel_.store(false);
  progress_->setRange(0, 2 * static_cast<int>(ds->frames.size()));
  progress_->setValue(0);
  progress_->show();
  cancel_button_->show();
  status_label_->setText(refine_poses ? tr("Fusing %1 frame(s)…").arg(ds->frames.size())
                                      : tr("Fusing %1 frame(s) at the forward-kinematics poses…").arg(ds->frames.size()));
  auto source = source_;  // keeps the dataset alive
  const Parameters params = params_->parameters();
  // A fusion at the given poses completes the shown fusion `target` (its mesh for comparison).
  auto target = refine_poses ? nullptr : fused_;
  sequence_future_ = QtConcurrent::run([this, source, params, refine_poses, target] {
    auto fused = std::make_shared<FusedScene>();
    QString error;
    bool cancelled = false;
    try {
      *fused = build_fused_scene(*source->dataset(), params, [this](int done, int) {
        QMetaObject::invokeMethod(this, [this, done] { progress_->setValue(done); });
      }, cancel_, refine_poses);
    } catch (const FusionCancelled&) {
      cancelled = true;
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(this, [this, fused, error, cancelled, refine_poses, target] {
      progress_->hide();
      cancel_button_->hide();
      sequence_running_ = false;
      if (cancelled) {
        status_label_->setText(tr("Fusion cancelled"));
        return emit fusionFinished(false);
      }
      if (!error.isEmpty()) {
        show_error(error);
        return emit fusionFinished(false);
      }
      if (!refine_poses) {
        if (!target || target != fused_) return emit fusionFinished(false);  // another input or fusion since
        fused_->given_geometry = fused->geometry;
        given_mesh_ = true;
        if (fused_shown_ && !refined_action_->isChecked()) show_fused(false);
        status_label_->setText(tr("Forward-kinematics poses: mesh %1 triangles (refined poses: %2) — fusion %3 ms, mesh %4 ms")
                                   .arg(fused->triangles)
                                   .arg(fused_->triangles)
                                   .arg(fused->fuse_ms, 0, 'f', 0)
                                   .arg(fused->mesh_ms, 0, 'f', 0));
        return emit fusionFinished(true);
      }
      fused_ = fused;
      given_mesh_ = !fused->refined;  // not refined: both geometries are the given poses'
      fused_shown_ = true;
      {
        const QSignalBlocker block(refined_action_);  // a new fusion starts at the refined poses
        refined_action_->setChecked(true);
      }
      refined_action_->setEnabled(fused->refined);
      show_fused(true);
      fused_frusta_ = fused->frusta;
      fused_triangles_ = fused->triangles;
      QStringList lines;
      int rescan = 0;
      for (const auto& p : fused->groups) {
        rescan += p.rescan ? 1 : 0;
        lines << pose_line(p, fused->refined);
      }
      results_->set_pose_status(lines);
      const auto& m = fused->merged.map;
      status_label_->setText(
          tr("Fused %1 frame(s), %2 pose(s) (%3 to rescan): mesh %4 triangles; merged map %5; %8 — fusion %6 ms, mesh %7 ms")
              .arg(fused->frames)
              .arg(fused->frusta)
              .arg(rescan)
              .arg(fused->triangles)
              .arg(map_summary(m))
              .arg(fused->fuse_ms, 0, 'f', 0)
              .arg(fused->mesh_ms, 0, 'f', 0)
              .arg(refinement_summary(*fused)));
      emit fusionFinished(true);
    });
  });
}

void MainWindow::show_fused(bool reset_camera) {
  const bool refined = refined_action_->isChecked();
  const scene::SceneGeometry& g = refined ? fused_->geometry : fused_->given_geometry;
  view3d_->show_geometry(g, reset_camera);
  // The mesh then follows the shown frame's pose like a loaded mesh PLY (world frame).
  mesh_world_ = g.mesh;
  mesh_frame_ = last_.frame_index;
  std::vector<View3DWidget::Label> labels;
  // At the middle of each frustum's far end: the apices of nearby poses crowd together.
  const Eigen::Vector3d tip(0.0, 0.0, kFusedFrustumDepthM);
  for (const auto& p : fused_->groups) labels.push_back({(refined ? p.fused_pose : p.given_pose) * tip, pose_label(p)});
  view3d_->set_labels(labels);
}

void MainWindow::show_refined_poses(bool refined) {
  if (refined_action_->isChecked() != refined) return refined_action_->setChecked(refined);  // re-enters
  if (!fused_ || !fused_shown_) return;
  show_fused(false);
  if (refined) return status_label_->setText(tr("Refined poses: %1").arg(refinement_summary(*fused_)));
  if (given_mesh_) return status_label_->setText(tr("Forward-kinematics poses (mesh fused with them)"));
  if (sequence_running_)
    return status_label_->setText(tr("Forward-kinematics poses: frusta and map; the mesh is still the refined one"));
  start_fusion(false);  // the mesh at these poses, once, on the worker
}

bool MainWindow::refined_poses_shown() const { return refined_action_->isChecked(); }

std::vector<Eigen::Vector3d> MainWindow::fused_frustum_centres() const {
  std::vector<Eigen::Vector3d> out;
  if (!fused_ || !fused_shown_) return out;
  for (const auto& p : fused_->groups)
    out.push_back((refined_action_->isChecked() ? p.fused_pose : p.given_pose).translation());
  return out;
}

void MainWindow::leave_fused_view() {
  if (!fused_shown_) return;
  fused_shown_ = false;
  refined_action_->setEnabled(false);
  view3d_->set_labels({});
}

void MainWindow::add_recent(const QString& path) {
  QSettings s;
  QStringList list = s.value("files/recent").toStringList();
  const QString abs = QFileInfo(path).absoluteFilePath();
  list.removeAll(abs);
  list.prepend(abs);
  while (list.size() > kMaxRecent) list.removeLast();
  s.setValue("files/recent", list);
  rebuild_recent_menu();
}

void MainWindow::rebuild_recent_menu() {
  if (!recent_menu_) return;
  recent_menu_->clear();
  for (const QString& p : QSettings().value("files/recent").toStringList())
    recent_menu_->addAction(p, this, [this, p] { open_input(p); });
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

void MainWindow::closeEvent(QCloseEvent* e) {
  cancel_.store(true);
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
  s.setValue("params/last", QByteArray::fromStdString(params_->parameters().to_json().dump()));
  QMainWindow::closeEvent(e);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (!urls.isEmpty() && urls.first().isLocalFile()) open_input(urls.first().toLocalFile());
}

}  // namespace tunnelmap::ui
