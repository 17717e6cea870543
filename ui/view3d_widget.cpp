#include "ui/view3d_widget.h"

#include <vtkGenericOpenGLRenderWindow.h>

namespace tunnelmap::ui {

View3DWidget::View3DWidget(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  setRenderWindow(window);
  window->AddRenderer(scene_.renderer());
  setMinimumSize(320, 240);
}

void View3DWidget::show_frame(const scene::ProcessedFrame& processed, bool reset_camera,
                              bool rebuild_cloud) {
  scene_.update(processed.scene_data(), rebuild_cloud);
  if (reset_camera) scene_.apply_view(scene::ViewPreset::Along);
  else scene_.renderer()->ResetCameraClippingRange();
  renderWindow()->Render();
  update();
}

void View3DWidget::clear() {
  scene_.clear();
  renderWindow()->Render();
  update();
}

void View3DWidget::set_layer_visible(scene::Layer layer, bool visible) {
  scene_.set_layer_visible(layer, visible);
  renderWindow()->Render();
  update();
}

void View3DWidget::apply_view(scene::ViewPreset view) {
  scene_.apply_view(view);
  renderWindow()->Render();
  update();
}

}  // namespace tunnelmap::ui
