#include "ui/mesh_opener.h"

#include <atomic>

#include "ui/background_job.h"
#include "ui/mesh_overlay.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

MeshOpener::MeshOpener(WindowContext& ctx, Show show, QObject* parent)
    : QObject(parent), ctx_(ctx), show_(std::move(show)) {}

bool MeshOpener::open(const QString& path) {
  if (ctx_.job->running()) {
    ctx_.status->show_error(tr("%1: wait for the running job, or cancel it, before opening a mesh").arg(path));
    return false;
  }
  ctx_.status->show_progress(0);  // busy while the file is read, then the pieces
  ctx_.status->set_text(tr("Opening mesh %1…").arg(path));
  const std::atomic<bool>& cancel = ctx_.job->cancel_flag();
  ctx_.job->start([this, path, &cancel] {
    vtkSmartPointer<vtkPolyData> mesh;
    QString error;
    try {
      mesh = read_mesh_ply(path.toStdString(), [this, &cancel](int done, int total) {
        QMetaObject::invokeMethod(this, [this, done, total] { ctx_.status->set_progress(done, total); });
        return !cancel.load();
      });
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    if (cancel.load()) mesh = nullptr;  // a cancel while the file was read
    QMetaObject::invokeMethod(this, [=] { finish(path, mesh, error); });
  });
  return true;
}

// On the GUI thread: the mesh swapped into the view.
void MeshOpener::finish(const QString& path, vtkSmartPointer<vtkPolyData> mesh, const QString& error) {
  ctx_.status->hide_progress();
  ctx_.job->finished();
  if (!error.isEmpty()) {
    ctx_.status->show_error(error);
    return emit opened(false);
  }
  if (!mesh) {
    ctx_.status->set_text(tr("Opening mesh %1 cancelled").arg(path));
    return emit opened(false);
  }
  show_(mesh);
  ctx_.status->set_text(tr("Mesh %1: %2 vertices, %3 triangles")
                            .arg(path)
                            .arg(mesh->GetNumberOfPoints())
                            .arg(mesh->GetNumberOfPolys()));
  emit opened(true);
}

}  // namespace tunnelmap::ui
