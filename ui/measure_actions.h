#pragma once
// View > Measure in 3D and Clear measurement: two clicks in the 3D view (or the depth view)
// measure a distance, shown in the status line.
class QMenu;

namespace tunnelmap::ui {

class DepthViewWidget;
class View3DWidget;
class WindowStatus;

void add_measure_actions(QMenu* view, View3DWidget* view3d, DepthViewWidget* depth, WindowStatus* status);

}  // namespace tunnelmap::ui
