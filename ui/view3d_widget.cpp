#include "ui/view3d_widget.h"

#include <QMouseEvent>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkTextProperty.h>

namespace tunnelmap::ui {

View3DWidget::View3DWidget(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  // No multisampling: VTK's default 4x MSAA quadruples the per-fragment work, which a software
  // renderer (llvmpipe under Xvfb or on machines without a GPU) pays on every point.
  window->SetMultiSamples(0);
  setRenderWindow(window);
  window->AddRenderer(scene_.renderer());
  scene_.set_legend_background(true);
  setMinimumSize(320, 240);
}

void View3DWidget::show_frame(const scene::ProcessedFrame& processed, bool reset_camera,
                              bool rebuild_cloud) {
  scene_.update(processed.scene_data(), rebuild_cloud);
  finish_update(reset_camera);
}

void View3DWidget::show_geometry(const scene::SceneGeometry& geometry, bool reset_camera) {
  scene_.set_geometry(geometry);
  finish_update(reset_camera);
}

void View3DWidget::set_mesh(vtkPolyData* mesh) {
  scene_.set_mesh(mesh);
  renderWindow()->Render();
  update();
}

void View3DWidget::finish_update(bool reset_camera) {
  if (reset_camera) scene_.apply_view(scene::ViewPreset::Along);
  else scene_.renderer()->ResetCameraClippingRange();
  renderWindow()->Render();
  update();
}

void View3DWidget::look_like(const Eigen::Isometry3d& camera_to_world) {
  const Eigen::Vector3d eye = camera_to_world.translation();
  const Eigen::Vector3d ahead = camera_to_world * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d up = -(camera_to_world.linear() * Eigen::Vector3d::UnitY());  // image y points down
  vtkCamera* cam = scene_.renderer()->GetActiveCamera();
  cam->SetPosition(eye.data());
  cam->SetFocalPoint(ahead.data());
  cam->SetViewUp(up.data());
  cam->SetViewAngle(45.0);
  scene_.renderer()->ResetCameraClippingRange();
  renderWindow()->Render();
  update();
}

void View3DWidget::clear() {
  scene_.clear();
  for (auto& a : labels_) scene_.renderer()->RemoveActor(a);
  labels_.clear();
  renderWindow()->Render();
  update();
}

void View3DWidget::set_layer_visible(scene::Layer layer, bool visible) {
  scene_.set_layer_visible(layer, visible);
  if (layer == scene::Layer::Frustum)
    for (auto& a : labels_) a->SetVisibility(visible);
  renderWindow()->Render();
  update();
}

void View3DWidget::apply_view(scene::ViewPreset view) {
  scene_.apply_view(view);
  renderWindow()->Render();
  update();
}

void View3DWidget::set_labels(const std::vector<Label>& labels) {
  for (auto& a : labels_) scene_.renderer()->RemoveActor(a);
  labels_.clear();
  for (const Label& l : labels) {
    auto a = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    a->SetInput(l.text.toUtf8().constData());
    a->SetPosition(l.position.x(), l.position.y(), l.position.z());
    a->SetDisplayOffset(0, 8);  // just above the point, centred: less often off the view's edge
    vtkTextProperty* t = a->GetTextProperty();
    t->SetJustificationToCentered();
    t->SetFontSize(13);
    t->SetColor(1.0, 1.0, 1.0);
    t->SetBackgroundColor(0.1, 0.1, 0.15);
    t->SetBackgroundOpacity(0.7);  // readable over the mesh
    t->SetFrame(false);
    a->SetVisibility(scene_.layer_visible(scene::Layer::Frustum));
    scene_.renderer()->AddActor(a);
    labels_.push_back(a);
  }
  renderWindow()->Render();
  update();
}

void View3DWidget::set_measuring(bool on) {
  measuring_ = on;
  setCursor(on ? Qt::CrossCursor : Qt::ArrowCursor);
}

void View3DWidget::clear_measurement() {
  if (scene_.measurements().empty()) return;
  scene_.set_measurements({});
  renderWindow()->Render();
  update();
  emit measurementChanged(QString());
}

bool View3DWidget::pick_at_widget(const QPoint& pixel) {
  // The depth buffer must hold the scene as shown: render, then read it in VTK's display
  // coordinates (device pixels, origin bottom-left).
  renderWindow()->Render();
  const double ratio = devicePixelRatioF();
  const int* size = renderWindow()->GetSize();
  const auto picked = scene_.pick_at(pixel.x() * ratio, size[1] - 1 - pixel.y() * ratio);
  if (!picked) return false;
  renderWindow()->Render();
  update();
  const auto& m = scene_.measurement();
  emit measurementChanged(m.distance_m() ? QString::fromStdString(m.label()) : tr("first point picked"));
  return true;
}

void View3DWidget::mousePressEvent(QMouseEvent* e) {
  if (measuring_ && e->button() == Qt::LeftButton && e->modifiers() == Qt::NoModifier) {
    pick_at_widget(e->pos());
    e->accept();
    return;
  }
  QVTKOpenGLNativeWidget::mousePressEvent(e);
}

QStringList View3DWidget::label_texts() const {
  QStringList out;
  for (const auto& a : labels_) out << QString::fromUtf8(a->GetInput());
  return out;
}

}  // namespace tunnelmap::ui
