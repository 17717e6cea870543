#include "ui/frame_controller.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QVBoxLayout>
#include <algorithm>

#include "core/mapping/map_options.h"
#include "ui/depth_view_widget.h"
#include "ui/file_dialogs.h"
#include "ui/frame_keys.h"
#include "ui/map_summary.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/timeline_widget.h"
#include "ui/view3d_widget.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {
constexpr int kDebounceMs = 60;  // while a slider is dragged; a release runs at once
}  // namespace

FrameController::FrameController(WindowContext& ctx)
    : QObject(ctx.window),
      ctx_(ctx),
      mesh_(ctx.view3d),
      opener_(ctx, [this](vtkSmartPointer<vtkPolyData> mesh) { mesh_.show(mesh, current_.get(), last_.frame_index); }) {
  connect(&opener_, &MeshOpener::opened, this, &FrameController::meshOpened);
  build_parameters_dock();
  build_results_dock();
  debounce_.setSingleShot(true);
  debounce_.setInterval(kDebounceMs);
  connect(&debounce_, &QTimer::timeout, this, [this] { request_run(true); });
  connect(ctx_.params, &ParameterPanel::parametersChanged, this, [this](bool immediate) {
    update_plot_reference();  // the design and tolerance are parameters
    if (immediate) request_run(true);
    else debounce_.start();
  });
  connect(&runner_, &PipelineRunner::finished, this, &FrameController::on_run_finished);
  // Reset all asks first, except in batch runs and tests, which are never asked (answer: no).
  ctx_.params->confirm_reset = [this, ask = ctx_.params->confirm_reset] { return !ctx_.dialogs->suppress && ask(); };
}

// The method selector above the parameters (the same choice as Processing > Method).
void FrameController::build_parameters_dock() {
  QMainWindow* window = ctx_.window;
  ctx_.params = new ParameterPanel(window);
  ctx_.params->setMinimumWidth(450);  // label + slider + value + reset per row
  auto* box = new QWidget(window);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* method_row = new QHBoxLayout;
  method_row->addWidget(new QLabel(tr("Method:"), box));
  method_combo_ = new QComboBox(box);
  method_combo_->setObjectName("methodCombo");
  for (Method m : {Method::Pgc, Method::Ransac, Method::Qhull})
    method_combo_->addItem(QString::fromUtf8(method_display_name(m)), static_cast<int>(m));
  method_row->addWidget(method_combo_, 1);
  layout->addLayout(method_row);
  layout->addWidget(ctx_.params, 1);
  connect(method_combo_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int i) {
    set_method(static_cast<Method>(method_combo_->itemData(i).toInt()));
  });
  params_dock_ = new QDockWidget(tr("Parameters"), window);
  params_dock_->setObjectName("parametersDock");
  params_dock_->setWidget(box);
  window->addDockWidget(Qt::LeftDockWidgetArea, params_dock_);
}

void FrameController::build_results_dock() {
  QMainWindow* window = ctx_.window;
  results_box_ = new QWidget(window);
  timeline_ = new TimelineWidget(results_box_);
  results_ = new ResultsPanel(results_box_);
  auto* layout = new QVBoxLayout(results_box_);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(timeline_);
  layout->addWidget(results_, 1);
  results_dock_ = new QDockWidget(tr("Frames and results"), window);
  results_dock_->setObjectName("resultsDock");
  results_dock_->setWidget(results_box_);
  window->addDockWidget(Qt::BottomDockWidgetArea, results_dock_);
  connect(timeline_, &TimelineWidget::frameRequested, this, [this](int i) { select_frame(i); });
  connect(results_, &ResultsPanel::frameActivated, this, [this](int i) { select_frame(i); });
}

void FrameController::add_method_menu(QMenu* processing) {
  QMenu* menu = processing->addMenu(tr("&Method"));
  method_actions_ = new QActionGroup(this);
  for (Method m : {Method::Pgc, Method::Ransac, Method::Qhull}) {
    QAction* a = menu->addAction(QString::fromUtf8(method_display_name(m)).replace("&", "&&"));
    a->setObjectName(QString("method_") + method_name(m));
    a->setCheckable(true);
    a->setChecked(m == method_);
    method_actions_->addAction(a);
    connect(a, &QAction::triggered, this, [this, m] { set_method(m); });
  }
}

void FrameController::build_navigation(QWidget* views) {
  add_frame_keys(this, {views, results_box_});
}

void FrameController::show_input() {
  const int frames = static_cast<int>(ctx_.source->size());
  frame_index_ = 0;
  reset_camera_ = true;
  mesh_.forget_placement();
  runner_.set_source(ctx_.source);  // drops cached results: every stage re-runs
  results_->clear();
  timeline_->set_frame_count(frames);
  results_->set_frame_count(frames);
  results_->set_current(0);
  const Dataset* ds = ctx_.dataset();
  results_->set_ground_truth(ds ? ds->gt_width_m : std::nullopt, ds ? ds->gt_height_m : std::nullopt);
  update_plot_reference();
}

void FrameController::reload_input() {
  runner_.set_source(ctx_.source);
  request_run(true);
}

bool FrameController::select_frame(int index) {
  if (!ctx_.source || index < 0 || index >= static_cast<int>(ctx_.source->size())) return false;
  timeline_->set_frame(index);
  results_->set_current(index);
  if (index == frame_index_) return true;  // already shown or requested
  frame_index_ = index;
  request_run(true);
  return true;
}

int FrameController::frame_count() const { return ctx_.source ? static_cast<int>(ctx_.source->size()) : 0; }

bool FrameController::step_frame(int delta) {
  if (!ctx_.source) return false;
  return select_frame(std::clamp(frame_index_ + delta, 0, frame_count() - 1));
}

void FrameController::request_run(bool immediate) {
  if (!ctx_.source || live_running()) return;  // the live view picks up changes with its next frame
  if (!immediate) return debounce_.start();
  debounce_.stop();
  runner_.request(frame_index_, ctx_.params->parameters(), method_);
}

void FrameController::set_method(Method method) {
  const int index = method_combo_->findData(static_cast<int>(method));
  if (method_combo_->currentIndex() != index) method_combo_->setCurrentIndex(index);  // re-enters
  for (QAction* a : method_actions_->actions())
    if (a->objectName() == QString("method_") + method_name(method)) a->setChecked(true);
  if (method == method_) return;
  method_ = method;
  ctx_.params->set_method(method);
  request_run(true);
}

void FrameController::update_plot_reference() {
  PlotReference ref;
  const StationMapOptions opt = station_map_options(ctx_.params->parameters());
  ref.tolerance_m = opt.tolerance_mm / 1000.0;
  const Dataset* ds = ctx_.dataset();
  if (ds && ds->gt_width_m && ds->gt_height_m) {
    ref.width_m = ds->gt_width_m;
    ref.height_m = ds->gt_height_m;
    ref.source = tr("ground truth");
  } else if (opt.design_width_m || opt.design_height_m) {
    ref.width_m = opt.design_width_m;
    ref.height_m = opt.design_height_m;
    ref.source = tr("design");
  }
  results_->plot()->set_reference(ref);
}

void FrameController::show_views(const RunOutcome& outcome) {
  last_ = outcome;
  current_ = outcome.processed;
  QElapsedTimer shown;
  shown.start();
  if (outcome.geometry)
    ctx_.view3d->show_geometry(*outcome.geometry, reset_camera_);
  else
    ctx_.view3d->show_frame(*current_, reset_camera_);
  reset_camera_ = false;
  ctx_.depth_view->show_frame(current_, outcome.depth_image);
  last_show_ms_ = shown.nsecsElapsed() / 1e6;
  mesh_.follow(current_.get(), outcome.frame_index);  // another frame's pose
}

void FrameController::on_run_finished(const RunOutcome& outcome) {
  if (!outcome.processed) {
    last_ = outcome;
    return ctx_.status->show_error(outcome.error);
  }
  show_views(outcome);
  record_result(outcome);
  const auto& r = current_->result;
  const auto total = r.timings_ms.find("total");
  ctx_.status->set_text(tr("Frame %1/%2 — %8 — %3, %4 planes — pipeline %5 ms (from %6), update %7 ms")
                            .arg(outcome.frame_index + 1)
                            .arg(ctx_.source ? ctx_.source->size() : 0)
                            .arg(map_summary(r.map))
                            .arg(r.planes.planes.size())
                            .arg(total == r.timings_ms.end() ? 0.0 : total->second, 0, 'f', 1)
                            .arg(stage_name(outcome.from))
                            .arg(outcome.wall_ms, 0, 'f', 1)
                            .arg(QString::fromUtf8(method_display_name(outcome.method))));
  ++shown_runs_;
  emit frameShown();
}

// The results row of the shown frame.
void FrameController::record_result(const RunOutcome& outcome) {
  FrameRecord record = detection_record(outcome.frame_index, current_->frame.source, current_->result, outcome.method);
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
}

void FrameController::show_live_outcome(const RunOutcome& outcome, const QString& status) {
  if (!outcome.processed) {
    last_ = outcome;
    return ctx_.status->set_text(outcome.error);  // keep streaming
  }
  show_views(outcome);
  ctx_.status->set_text(status);
  ++shown_runs_;
  emit frameShown();
}

void FrameController::start_live() {
  reset_camera_ = true;
  results_->clear();
  timeline_->set_frame_count(0);
}

void FrameController::stop_live() {
  if (ctx_.source) timeline_->set_frame_count(static_cast<int>(ctx_.source->size()));
}

bool FrameController::open_mesh(const QString& path) { return opener_.open(path); }

}  // namespace tunnelmap::ui
