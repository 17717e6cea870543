// MainWindow, linked navigation: the timeline, the results table, the plot and the 3D view show
// the same frame, and a click on any of them (or a key) moves all of them through select_frame.
#include <QAction>
#include <algorithm>
#include <climits>

#include "core/mapping/map_options.h"
#include "ui/main_window.h"
#include "ui/parameter_panel.h"
#include "ui/results_panel.h"
#include "ui/timeline_widget.h"

namespace tunnelmap::ui {

bool MainWindow::select_frame(int index) {
  if (!source_ || index < 0 || index >= static_cast<int>(source_->size())) return false;
  timeline_->set_frame(index);
  results_->set_current(index);
  if (index == frame_index_) return true;  // already shown or requested
  frame_index_ = index;
  request_run(true);
  return true;
}

bool MainWindow::step_frame(int delta) {
  if (!source_) return false;
  const int last = static_cast<int>(source_->size()) - 1;
  return select_frame(std::clamp(frame_index_ + delta, 0, last));
}

void MainWindow::build_navigation(QWidget* views, QWidget* results) {
  connect(timeline_, &TimelineWidget::frameRequested, this, [this](int i) { select_frame(i); });
  connect(results_, &ResultsPanel::frameActivated, this, [this](int i) { select_frame(i); });
  // Keys act while the focus is in the 3D/2D views, the timeline, the table or the plot (not in
  // the parameter panel, whose sliders and spin boxes use the same keys).
  constexpr int kPage = 10;
  const struct {
    const char* name;
    const char* text;
    QKeySequence key;
    int delta;  // INT_MIN / INT_MAX: first / last
  } keys[] = {
      {"nextFrame", "Next frame", QKeySequence(Qt::Key_Right), 1},
      {"previousFrame", "Previous frame", QKeySequence(Qt::Key_Left), -1},
      {"pageForward", "10 frames forward", QKeySequence(Qt::Key_PageDown), kPage},
      {"pageBack", "10 frames back", QKeySequence(Qt::Key_PageUp), -kPage},
      {"firstFrame", "First frame", QKeySequence(Qt::Key_Home), INT_MIN},
      {"lastFrame", "Last frame", QKeySequence(Qt::Key_End), INT_MAX},
  };
  for (const auto& k : keys) {
    auto* a = new QAction(tr(k.text), this);
    a->setObjectName(k.name);
    a->setShortcut(k.key);
    a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    const int delta = k.delta;
    connect(a, &QAction::triggered, this, [this, delta] {
      if (!source_) return;
      if (delta == INT_MIN) select_frame(0);
      else if (delta == INT_MAX) select_frame(static_cast<int>(source_->size()) - 1);
      else step_frame(delta);
    });
    views->addAction(a);
    results->addAction(a);
  }
}

void MainWindow::update_plot_reference() {
  PlotReference ref;
  const StationMapOptions opt = station_map_options(params_->parameters());
  ref.tolerance_m = opt.tolerance_mm / 1000.0;
  const Dataset* ds = source_ ? source_->dataset() : nullptr;
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

}  // namespace tunnelmap::ui
