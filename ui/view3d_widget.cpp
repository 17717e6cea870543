#include "ui/view3d_widget.h"

#include <vtkGenericOpenGLRenderWindow.h>

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
