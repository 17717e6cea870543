#pragma once
// The 3D view: VTK's Qt widget showing the shared TunnelScene (ui/scene), with layer toggles and
// camera presets driven from the main window's View menu.
#include <QStringList>
#include <QVTKOpenGLNativeWidget.h>
#include <vector>

#include <Eigen/Geometry>
#include <vtkBillboardTextActor3D.h>

#include "ui/scene/processed_frame.h"
#include "ui/scene/tunnel_scene.h"

namespace tunnelmap::ui {

class View3DWidget : public QVTKOpenGLNativeWidget {
  Q_OBJECT
 public:
  explicit View3DWidget(QWidget* parent = nullptr);

  scene::TunnelScene& scene() { return scene_; }
  // Rebuilds the scene; resets the camera on the first frame of an input only.
  // `rebuild_cloud` false keeps the point-cloud layer (only later stages changed).
  void show_frame(const scene::ProcessedFrame& processed, bool reset_camera, bool rebuild_cloud = true);
  // Shows geometry built off the GUI thread (PipelineRunner): only swaps inputs and renders.
  void show_geometry(const scene::SceneGeometry& geometry, bool reset_camera);
  void set_mesh(vtkPolyData* mesh);  // null clears the mesh layer
  void clear();
  void set_layer_visible(scene::Layer layer, bool visible);
  void apply_view(scene::ViewPreset view);
  // Looks the way a camera at `camera_to_world` does, from where it stands (world-frame scene).
  void look_like(const Eigen::Isometry3d& camera_to_world);

  // Small screen-facing text labels at world points (e.g. one per camera frustum), shown with
  // the frustum layer; an empty list removes them.
  struct Label {
    Eigen::Vector3d position;
    QString text;
  };
  void set_labels(const std::vector<Label>& labels);
  QStringList label_texts() const;

  // Measure tool (View > Measure in 3D): while on, a left click picks the surface under the
  // cursor and two picks give their distance, drawn in the scene; the other buttons and the
  // wheel still move the camera.
  void set_measuring(bool on);
  bool measuring() const { return measuring_; }
  void clear_measurement();
  // Picks at a widget pixel (what a click does); false over the background.
  bool pick_at_widget(const QPoint& pixel);

 signals:
  // "1234.5 mm", "first point picked" or "" after a clear.
  void measurementChanged(const QString& text);

 protected:
  void mousePressEvent(QMouseEvent* e) override;

 private:
  void finish_update(bool reset_camera);

  scene::TunnelScene scene_;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> labels_;
  bool measuring_ = false;
};

}  // namespace tunnelmap::ui
