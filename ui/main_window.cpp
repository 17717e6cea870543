// The inspection window: layout, input and frame selection, re-runs of the shown frame, presets,
// the mesh layer, settings. Menus, device, sequence, fusion and exports: main_window_*.cpp and
// results_export.cpp.
#include "ui/main_window.h"

#include <algorithm>

#include <QComboBox>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QScreen>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include "core/io/ply_mesh_reader.h"
#include "core/recordings/recording.h"
#include "core/tunnel/tunnel_options.h"
#include "core/util/error.h"
#include "ui/depth_view_widget.h"
#include "ui/fused_scene.h"
#include "ui/live_view.h"
#include "ui/map_summary.h"
#include "ui/mesh_layer.h"
#include "ui/message_log.h"
#include "ui/parameter_panel.h"
#include "ui/recording_opener.h"
#include "ui/results_panel.h"
#include "ui/timeline_widget.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

namespace {
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

  status_label_ = new QLabel(tr("Ready"), this);
  progress_ = new QProgressBar(this);
  progress_->setMaximumWidth(200);
  progress_->hide();
  cancel_button_ = new QPushButton(tr("Cancel"), this);
  cancel_button_->hide();
  statusBar()->addWidget(status_label_, 1);
  // The loaded preset ("Preset: field", "(modified)" after an edit) and, when the open dataset
  // names its tunnel kind, a button offering the matching preset (never a dialog).
  offer_preset_ = new QPushButton(this);
  offer_preset_->setObjectName("offerPreset");
  offer_preset_->hide();
  statusBar()->addPermanentWidget(offer_preset_);
  connect(offer_preset_, &QPushButton::clicked, this, [this] {
    if (load_preset(offer_preset_->property("path").toString())) offer_preset_->hide();
  });
  preset_label_ = new QLabel(this);
  preset_label_->setObjectName("presetLabel");
  statusBar()->addPermanentWidget(preset_label_);
  statusBar()->addPermanentWidget(progress_);
  statusBar()->addPermanentWidget(cancel_button_);
  connect(cancel_button_, &QPushButton::clicked, this, &MainWindow::cancel_sequence);
  connect_recording_opener();
  // Errors: one line in the status bar, all of them in the Messages dock (never a dialog).
  messages_ = new MessageLog(this);
  messages_dock_ = new QDockWidget(tr("Messages"), this);
  messages_dock_->setObjectName("messagesDock");
  messages_dock_->setWidget(messages_);
  addDockWidget(Qt::BottomDockWidgetArea, messages_dock_);
  messages_dock_->hide();
  messages_button_ = new QToolButton(this);
  messages_button_->setObjectName("messagesButton");
  messages_button_->setAutoRaise(true);
  messages_button_->hide();  // until the first message
  statusBar()->addPermanentWidget(messages_button_);
  connect(messages_button_, &QToolButton::clicked, this, [this] {
    messages_dock_->setVisible(!messages_dock_->isVisible());
    if (messages_dock_->isVisible()) messages_dock_->raise();
  });
  connect(messages_, &MessageLog::changed, this, [this](int n) {
    messages_button_->setText(tr("⚠ %n message(s)", nullptr, n));
    messages_button_->setVisible(n > 0);
  });

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
    update_plot_reference();  // the design and tolerance are parameters
    update_preset_status();
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
  build_navigation(split, bottom);
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
  // Reset all asks first, except in batch runs and tests, which are never asked (answer: no).
  params_->confirm_reset = [this, ask = params_->confirm_reset] { return !suppress_dialogs && ask(); };
  build_menus();

  QSettings settings;
  if (!restoreGeometry(settings.value("window/geometry").toByteArray()))
    apply_first_start_layout(params_dock, results_dock);
  restoreState(settings.value("window/state").toByteArray());
  const QByteArray last = settings.value("params/last").toByteArray();
  if (!last.isEmpty()) {
    try {
      Parameters p;
      p.apply_json(nlohmann::json::parse(last.toStdString()), "settings");
      // The last design belonged to the last input, not to whatever opens next.
      p.set(tunnel_keys::design_width_m, 0.0);
      p.set(tunnel_keys::design_height_m, 0.0);
      params_->set_initial_parameters(p);
    } catch (const std::exception&) {
      // Stale settings from another version: defaults.
    }
  }
  restore_view_settings();  // layers, method, camera (main_window_session.cpp)
  update_preset_status();
}

// Without a saved layout: 1600 x 900 where the screen allows, a parameter panel wide enough
// for 200 px sliders (a 60 px slider turned one pixel into a decade of min points), and room
// for eight result rows under the views.
void MainWindow::apply_first_start_layout(QDockWidget* params, QDockWidget* results) {
  const QScreen* screen = QGuiApplication::primaryScreen();
  const QSize room = screen ? screen->availableGeometry().size() : QSize(1600, 900);
  resize(std::min(1600, room.width()), std::min(900, room.height()));
  resizeDocks({params}, {560}, Qt::Horizontal);
  resizeDocks({results}, {320}, Qt::Vertical);
}

MainWindow::~MainWindow() {
  live_->stop();
  cancel_.store(true);
  sequence_future_.waitForFinished();
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
  messages_->add(message);
  emit errorShown(message);
}

bool MainWindow::open_input(const QString& path) {
  std::shared_ptr<const FrameSource> source;
  try {
    source = tunnelmap::open_input(path.toStdString(), read_options_for(path));
    if (source->size() == 0) throw InputError(path.toStdString(), "contains no frames");
    source->load(0);  // validate now: a bad file must not replace the current input
  } catch (const std::exception& e) {
    show_error(QString::fromStdString(e.what()));
    return false;
  }
  adopt_input(path, source);
  return true;
}

bool MainWindow::open_interactively(const QString& path) {
  if (!recordings::is_recording_path(path.toStdString())) return open_input(path);
  if (!recordings_->open(path, read_options_for(path))) {
    show_error(tr("%1: another recording is still being opened").arg(path));
    return false;
  }
  return true;
}

void MainWindow::adopt_input(const QString& path, std::shared_ptr<const FrameSource> source) {
  cancel_.store(true);
  if (live_->running()) stop_live_view();
  leave_fused_view();
  fused_.reset();  // a running compare fusion then finds nothing to attach to
  forget_review_state();
  const QString previous = input_path_;
  source_ = source;
  input_path_ = path;
  frame_index_ = 0;
  reset_camera_ = true;
  mesh_frame_ = -1;
  runner_.set_source(source_);
  results_->clear();
  timeline_->set_frame_count(static_cast<int>(source_->size()));
  results_->set_frame_count(static_cast<int>(source_->size()));
  results_->set_current(0);
  if (!previous.isEmpty() && previous != path) clear_design(previous);
  const Dataset* ds = source_->dataset();
  results_->set_ground_truth(ds ? ds->gt_width_m : std::nullopt, ds ? ds->gt_height_m : std::nullopt);
  update_plot_reference();
  update_preset_status();  // the window title names the input and the preset
  offer_matching_preset();
  add_recent(path);
  QSettings().setValue("files/lastFolder", QFileInfo(path).absolutePath());
  status_label_->setText(tr("Opened %1 (%2 frame(s))").arg(path).arg(source_->size()));
  request_run(true);
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
  review_frame_shown();
  if (mesh_world_ && outcome.frame_index != mesh_frame_) show_mesh();  // another frame's pose
}

void MainWindow::set_method(Method method) {
  const int index = method_combo_->findData(static_cast<int>(method));
  if (method_combo_->currentIndex() != index) method_combo_->setCurrentIndex(index);  // re-enters
  for (QAction* a : method_actions_->actions())
    if (a->objectName() == QString("method_") + method_name(method)) a->setChecked(true);
  if (method == method_) return;
  method_ = method;
  params_->set_method(method);
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
  FrameRecord record =
      detection_record(outcome.frame_index, current_->frame.source, current_->result, outcome.method);
  // A partial re-run's "total" times only the stages it re-ran (0.1 ms for the tunnel stage);
  // the row shows the whole pipeline's time of the result on screen: the sum of its stages.
  if (outcome.from != Stage::Cloud) {
    double full = 0.0;
    for (const char* stage : {"cloud", "normals", "planes", "tunnel"}) {
      const auto it = record.timings_ms.find(stage);
      if (it != record.timings_ms.end()) full += it->second;
    }
    record.timings_ms["total"] = full;
  }
  // A row made with the same method and parameters stays: a sequence's row carries the context
  // of the frames before it (as `detect` computes it), which a frame viewed alone lacks.
  const auto& rows = results_->records();
  const bool same_row = std::any_of(rows.begin(), rows.end(), [&](const FrameRecord& r) {
    return r.index == outcome.frame_index && r.method == outcome.method &&
           results_->parameter_set(r.param_set) == outcome.params;
  });
  if (!same_row) results_->set_record(record, outcome.params);
  results_->set_current(outcome.frame_index);
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

bool MainWindow::open_mesh(const QString& path) {
  vtkSmartPointer<vtkPolyData> mesh;
  try {
    const std::string file = path.toStdString();
    const PlyMesh ply = read_ply_mesh(file);  // InputError(file, problem) on any bad input
    if (ply.vertices.empty()) throw InputError(file, "PLY has no vertices");
    if (ply.triangles.empty()) throw InputError(file, "PLY has no faces (not a mesh)");
    mesh = ply_mesh_polydata(ply);
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
  view3d_->set_mesh(mesh_in_camera_frame(mesh_world_, current_->frame.pose->inverse()));
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
    recent_menu_->addAction(p, this, [this, p] { open_interactively(p); });
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

void MainWindow::closeEvent(QCloseEvent* e) {
  cancel_.store(true);
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
  s.setValue("params/last", QByteArray::fromStdString(params_->parameters().to_json().dump()));
  save_view_settings();
  QMainWindow::closeEvent(e);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (!urls.isEmpty() && urls.first().isLocalFile()) open_interactively(urls.first().toLocalFile());
}

}  // namespace tunnelmap::ui
