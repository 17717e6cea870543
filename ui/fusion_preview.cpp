// First: TBB (through the volume's header) must be read before Qt defines `emit`.
#include "ui/preview_mesher.h"

#include "core/fusion/fusion_options.h"
#include "core/kinematics/frame_pose.h"

#include "ui/fusion_preview.h"

#include <QElapsedTimer>

#include "ui/view3d_widget.h"
#include "ui/window_context.h"
#include "ui/window_status.h"

namespace tunnelmap::ui {

namespace {
// The mesh alone in the world frame: no single frame's cloud, and the frusta and merged map
// come with the final mesh.
scene::SceneGeometry mesh_only(vtkSmartPointer<vtkPolyData> mesh) {
  scene::SceneGeometry g;
  for (auto* layer : {&g.cloud, &g.planes, &g.boundary, &g.traversable, &g.forbidden, &g.frustum})
    *layer = vtkSmartPointer<vtkPolyData>::New();
  g.mesh = std::move(mesh);
  return g;
}
}  // namespace

FusionPreview::FusionPreview(WindowContext& ctx, QObject* parent)
    : QObject(parent), ctx_(ctx), interval_ms_(kPreviewIntervalMs) {}

VolumeWatcher FusionPreview::start(const Parameters& params, const Dataset& dataset) {
  shown_.clear();
  worker_ms_ = show_ms_ = 0.0;
  showing_ = interval_ms_ >= 0;
  if (!showing_) return {};
  // Its given pose: the refined one is not known yet, and framing needs no better.
  first_camera_ = resolve_frame_pose(dataset, 0).pose.value_or(Eigen::Isometry3d::Identity());
  channel_ = std::make_shared<PreviewChannel>();
  auto mesher = std::make_shared<PreviewMesher>(
      fusion_options(params).min_weight, std::chrono::milliseconds(interval_ms_), channel_,
      [this](PreviewMesh p) { QMetaObject::invokeMethod(this, [this, p] { show(p); }); });
  return [mesher](const SparseTsdfVolume& volume, int done, int total) { mesher->after_frame(volume, done, total); };
}

void FusionPreview::show(const PreviewMesh& p) {
  worker_ms_ += p.worker_ms;
  if (showing_) {
    QElapsedTimer t;
    t.start();
    ctx_.view3d->show_geometry(mesh_only(p.mesh), false);
    ctx_.view3d->set_labels({});
    if (shown_.isEmpty()) ctx_.view3d->look_like(first_camera_);  // framed once, then the user's
    shown_.push_back(p.triangles);
    ctx_.status->set_text(tr("Fusing: %1 of %2 frames, %3 triangles so far").arg(p.done).arg(p.total).arg(p.triangles));
    channel_->show_ms.store(static_cast<int>(t.elapsed()));
    show_ms_ += t.elapsed();
    emit previewShown(p.triangles);
  }
  channel_->in_flight.store(false);
}

}  // namespace tunnelmap::ui
