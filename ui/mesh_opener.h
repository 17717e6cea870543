#pragma once
// Opens a triangle mesh PLY without blocking the window: the file is read and cut into pieces
// on the window's background job (progress and Cancel in the status bar), then handed to `show`
// on the GUI thread. One job at a time: a mesh is not opened while another job runs.
#include <QObject>
#include <QString>
#include <functional>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace tunnelmap::ui {

struct WindowContext;

class MeshOpener : public QObject {
  Q_OBJECT
 public:
  using Show = std::function<void(vtkSmartPointer<vtkPolyData>)>;
  MeshOpener(WindowContext& ctx, Show show, QObject* parent = nullptr);

  // False, and nothing started, while another job runs; else `opened` tells the outcome.
  bool open(const QString& path);

 signals:
  void opened(bool ok);  // shown, or failed or cancelled

 private:
  void finish(const QString& path, vtkSmartPointer<vtkPolyData> mesh, const QString& error);

  WindowContext& ctx_;
  Show show_;
};

}  // namespace tunnelmap::ui
