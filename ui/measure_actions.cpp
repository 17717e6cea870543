#include "ui/measure_actions.h"

#include <QAction>
#include <QMenu>

#include "ui/depth_view_widget.h"
#include "ui/view3d_widget.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

void add_measure_actions(QMenu* view, View3DWidget* view3d, DepthViewWidget* depth, WindowStatus* status) {
  view->addSeparator();
  QAction* measure = view->addAction(QObject::tr("&Measure in 3D"));
  measure->setObjectName("measure3d");
  measure->setCheckable(true);
  measure->setShortcut(QKeySequence("M"));
  measure->setStatusTip(QObject::tr("Click two points in the 3D view to measure their distance"));
  QObject::connect(measure, &QAction::toggled, view3d, &View3DWidget::set_measuring);
  QObject::connect(measure, &QAction::toggled, depth, &DepthViewWidget::set_measuring);
  view->addAction(QObject::tr("C&lear measurement"), view3d, [view3d, depth] {
    view3d->clear_measurement();
    depth->clear_measurement();
  }, QKeySequence("Esc"));
  QObject::connect(view3d, &View3DWidget::measurementChanged, status, [status](const QString& text) {
    if (!text.isEmpty()) status->set_text(QObject::tr("3D measurement: %1").arg(text));
  });
  QObject::connect(depth, &DepthViewWidget::measurementChanged, status, [status](const QString& text) {
    if (!text.isEmpty()) status->set_text(QObject::tr("2D view measurement: %1").arg(text));
  });
}

}  // namespace tunnelmap::ui
