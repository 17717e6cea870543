#include "ui/main_window.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMenu>
#include <QMenuBar>
#include <QMimeData>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QUndoStack>
#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/tunnel/tunnel_options.h"
#include "ui/depth_view_widget.h"
#include "ui/live_view.h"
#include "ui/parameter_panel.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent),
      status_(new WindowStatus(this)),
      dialogs_(std::make_unique<FileDialogs>(this, status_)),
      choose_open_path(dialogs_->choose_open_path),
      choose_save_path(dialogs_->choose_save_path),
      confirm_overwrite(dialogs_->confirm_overwrite),
      suppress_dialogs(dialogs_->suppress) {
  setWindowTitle("TunnelMap");
  setAcceptDrops(true);
  ctx_.window = this;
  ctx_.status = status_;
  ctx_.dialogs = dialogs_.get();
  ctx_.job = &job_;
  QWidget* views = build_views();
  create_controllers();
  frames_->build_navigation(views);
  connect_input_changes();
  build_menus();
  restore_settings();
}

MainWindow::~MainWindow() {
  devices_->live_view()->stop();
  job_.cancel();
  job_.wait();
  // The controllers go before the context and the job they refer to (members die before the
  // QObject children would); the docks and widgets they made stay children of the window.
  for (QObject* c : std::initializer_list<QObject*>{exports_, sessions_, intrinsics_, devices_, fusion_, review_,
                                                    sequence_, presets_, inputs_, frames_})
    delete c;
}

QWidget* MainWindow::build_views() {
  ctx_.view3d = new View3DWidget(this);
  ctx_.depth_view = new DepthViewWidget(this);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(ctx_.view3d);
  split->addWidget(ctx_.depth_view);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  setCentralWidget(split);
  connect(ctx_.depth_view, &DepthViewWidget::hovered, this, [this](const QString& t) { status_->flash(t, 3000); });
  return split;
}

void MainWindow::create_controllers() {
  frames_ = new FrameController(ctx_);  // the parameter panel first: every other one reads it
  inputs_ = new InputController(ctx_);
  presets_ = new PresetController(ctx_);
  status_->add_permanent_widgets();  // right of the preset's
  sequence_ = new SequenceController(ctx_, frames_->results());
  sequence_->method = [this] { return frames_->method(); };
  review_ = new ReviewController(ctx_, frames_);
  fusion_ = new FusionController(ctx_, frames_);
  devices_ = new DeviceController(ctx_, frames_);
  fusion_->stop_live = [this] { devices_->stop_live_view(); };
  intrinsics_ = new IntrinsicsController(ctx_, frames_);
  inputs_->read_options = [this](const QString& input) { return intrinsics_->read_options_for(input); };
  sessions_ = new SessionController(ctx_, {frames_, inputs_, intrinsics_, presets_, review_});
  exports_ = new ExportController(ctx_, frames_, review_);
  connect(status_->cancel_button(), &QPushButton::clicked, this, [this] { job_.cancel(); });
  // Last, so that every controller has followed the frame before a listener hears of it.
  connect(frames_, &FrameController::frameShown, this, &MainWindow::frameShown);
  connect(frames_, &FrameController::meshOpened, this, &MainWindow::meshOpened);
  connect(review_, &ReviewController::tunnelMapped, this, &MainWindow::tunnelMapped);
  connect(fusion_, &FusionController::fusionFinished, this, &MainWindow::fusionFinished);
  connect(status_, &WindowStatus::errorShown, this, &MainWindow::errorShown);
}

// What a new input replaces, in order: the camera, the fusion and the map review of the old
// one; then its frames, a design typed for the old one, the preset line, and the first run.
void MainWindow::connect_input_changes() {
  connect(inputs_, &InputController::inputClosing, this, [this] {
    if (devices_->live()) devices_->stop_live_view();
    fusion_->forget();
    review_->forget();
  });
  connect(inputs_, &InputController::inputOpened, this, [this](const QString& previous) {
    frames_->show_input();
    if (!previous.isEmpty() && previous != ctx_.input_path) presets_->clear_design(previous);
    frames_->update_plot_reference();
    presets_->update_status();  // the window title names the input and the preset
    presets_->offer_matching_preset();
    frames_->request_run(true);
  });
  connect(devices_, &DeviceController::liveStarted, review_, &ReviewController::forget);
}

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  inputs_->add_open_actions(file);
  file->addAction(tr("Open &mesh…"), this, [this] {
    const QString path = dialogs_->ask_open_path(tr("Open mesh PLY"), tr("PLY (*.ply)"));
    if (!path.isEmpty()) frames_->open_mesh(path);
  })->setObjectName("openMesh");
  sessions_->add_actions(file);
  intrinsics_->add_actions(file);
  file->addSeparator();
  exports_->add_actions(file);
  file->addSeparator();
  sequence_->add_action(file)->setObjectName("processSequence");
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  // Edit: undo/redo of parameter changes (each completed edit, Reset all, a loaded preset).
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = ctx_.params->undo_stack()->createUndoAction(this, tr("&Undo"));
  undo->setObjectName("undo");
  undo->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Z));
  edit->addAction(undo);
  QAction* redo = ctx_.params->undo_stack()->createRedoAction(this, tr("&Redo"));
  redo->setObjectName("redo");
  redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
  edit->addAction(redo);

  QMenu* processing = menuBar()->addMenu(tr("&Processing"));
  frames_->add_method_menu(processing);
  sequence_->add_action(processing);
  fusion_->add_fuse_action(processing);
  devices_->add_menu(menuBar()->addMenu(tr("&Device")));
  QMenu* view = menuBar()->addMenu(tr("&View"));
  add_view_actions(view);
  review_->add_actions(processing, view);
}

// Layers, the fused view's poses and the camera presets.
void MainWindow::add_view_actions(QMenu* view) {
  View3DWidget* v = ctx_.view3d;
  for (scene::Layer layer : scene::all_layers()) {
    QAction* a = view->addAction(tr(scene::layer_title(layer)));
    a->setCheckable(true);
    a->setChecked(v->scene().layer_visible(layer));
    connect(a, &QAction::toggled, this, [v, layer](bool on) { v->set_layer_visible(layer, on); });
  }
  view->addSeparator();
  fusion_->add_view_actions(view);
  view->addSeparator();
  view->addAction(tr("Look &along the tunnel"), this, [v] { v->apply_view(scene::ViewPreset::Along); }, QKeySequence("1"));
  view->addAction(tr("From the &side"), this, [v] { v->apply_view(scene::ViewPreset::Side); }, QKeySequence("2"));
  view->addAction(tr("From &above"), this, [v] { v->apply_view(scene::ViewPreset::Top); }, QKeySequence("3"));
  view->addAction(tr("&Reset camera"), this, [v] { v->apply_view(scene::ViewPreset::Reset); }, QKeySequence("0"));
}

void MainWindow::restore_settings() {
  QSettings settings;
  if (!restoreGeometry(settings.value("window/geometry").toByteArray())) apply_first_start_layout();
  restoreState(settings.value("window/state").toByteArray());
  const QByteArray last = settings.value("params/last").toByteArray();
  if (!last.isEmpty()) {
    try {
      Parameters p;
      p.apply_json(nlohmann::json::parse(last.toStdString()), "settings");
      // The last design belonged to the last input, not to whatever opens next.
      p.set(tunnel_keys::design_width_m, 0.0);
      p.set(tunnel_keys::design_height_m, 0.0);
      ctx_.params->set_initial_parameters(p);
    } catch (const std::exception&) {
      // Stale settings from another version: defaults.
    }
  }
  sessions_->restore_view_settings();  // layers, method, camera
  presets_->update_status();
}

// Without a saved layout: 1600 x 900 where the screen allows, a parameter panel wide enough
// for 200 px sliders (a 60 px slider turned one pixel into a decade of min points), and room
// for eight result rows under the views.
void MainWindow::apply_first_start_layout() {
  const QScreen* screen = QGuiApplication::primaryScreen();
  const QSize room = screen ? screen->availableGeometry().size() : QSize(1600, 900);
  resize(std::min(1600, room.width()), std::min(900, room.height()));
  resizeDocks({frames_->parameters_dock()}, {560}, Qt::Horizontal);
  resizeDocks({frames_->results_dock()}, {320}, Qt::Vertical);
}

void MainWindow::closeEvent(QCloseEvent* e) {
  job_.cancel();
  QSettings s;
  s.setValue("window/geometry", saveGeometry());
  s.setValue("window/state", saveState());
  s.setValue("params/last", QByteArray::fromStdString(ctx_.params->parameters().to_json().dump()));
  sessions_->save_view_settings();
  QMainWindow::closeEvent(e);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  const auto urls = e->mimeData()->urls();
  if (!urls.isEmpty() && urls.first().isLocalFile()) inputs_->open_interactively(urls.first().toLocalFile());
}

}  // namespace tunnelmap::ui
