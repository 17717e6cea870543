#pragma once
// The frame navigation keys (Left/Right, Page Up/Down, Home/End) over the widgets that show
// frames: they act while the focus is in the views, the timeline, the table or the plot, not
// in the parameter panel, whose sliders and spin boxes use the same keys.
#include <initializer_list>

class QWidget;

namespace tunnelmap::ui {

class FrameController;

void add_frame_keys(FrameController* frames, std::initializer_list<QWidget*> over);

}  // namespace tunnelmap::ui
