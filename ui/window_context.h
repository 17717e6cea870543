#pragma once
// What the window's controllers share: the central views, the status bar, the file dialogs,
// the one background job, the parameter panel and the open input. Each controller owns its
// own docks, actions and state; this is only what more than one of them reads.
#include <QString>
#include <memory>

#include "core/io/frame_source.h"

class QMainWindow;

namespace tunnelmap::ui {

class BackgroundJob;
class DepthViewWidget;
struct FileDialogs;
class ParameterPanel;
class View3DWidget;
class WindowStatus;

struct WindowContext {
  QMainWindow* window = nullptr;
  View3DWidget* view3d = nullptr;
  DepthViewWidget* depth_view = nullptr;
  WindowStatus* status = nullptr;
  FileDialogs* dialogs = nullptr;
  BackgroundJob* job = nullptr;
  ParameterPanel* params = nullptr;  // made by the frame controller, with its dock

  // The open input; InputController replaces both together.
  std::shared_ptr<const FrameSource> source;
  QString input_path;
  const Dataset* dataset() const { return source ? source->dataset() : nullptr; }
};

}  // namespace tunnelmap::ui
