#pragma once
// TunnelScene: the VTK scene of one processed frame, one actor per layer. It owns a renderer
// that the caller adds to any render window: the Qt widget in the GUI, an OSMesa-backed window
// in tunnelmap-render. No Qt here, so both executables share exactly this code.
#include <array>
#include <memory>
#include <vector>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkAxesActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "ui/scene/camera_presets.h"
#include "ui/scene/image_checks.h"
#include "ui/scene/measurement.h"
#include "ui/scene/scene_colors.h"
#include "ui/scene/scene_data.h"
#include "ui/scene/scene_geometry.h"
#include "ui/scene/scene_layers.h"
#include "ui/scene/scene_legend.h"

namespace tunnelmap::scene {

class TunnelScene {
 public:
  TunnelScene();
  ~TunnelScene();
  TunnelScene(const TunnelScene&) = delete;  // the renderer's observer points at this object
  TunnelScene& operator=(const TunnelScene&) = delete;

  vtkRenderer* renderer() const { return renderer_; }

  // Rebuilds the layers from `data` (pointers need only live during the call). With
  // `rebuild_cloud` false the point-cloud layer is kept (its input did not change).
  void update(const SceneData& data, bool rebuild_cloud = true);
  // Shows geometry built elsewhere (e.g. on a worker thread); null cloud/mesh keep theirs.
  void set_geometry(const SceneGeometry& geometry);
  // A mesh (e.g. a fused mesh PLY) in the camera frame of the shown frame; null clears it.
  void set_mesh(vtkPolyData* mesh);
  void clear();

  // A dark box behind the legend, readable over the zones. Off by default: under OSMesa the box
  // hides the entries (VTK 9.1), so only the GUI (GLX) turns it on.
  void set_legend_background(bool on);

  // Point-layer decimation for update() (see scene_geometry.h); <= 0: full density.
  void set_max_display_points(int n) { max_points_ = n; }
  int max_display_points() const { return max_points_; }

  void set_layer_visible(Layer layer, bool visible);
  bool layer_visible(Layer layer) const { return visible_[static_cast<int>(layer)]; }
  // Visible and drawn in the current view: the frustum and the axes sit at the camera, so the
  // along view (from the camera) hides them whatever their toggles say.
  bool layer_shown(Layer layer) const;
  void show_only(const std::vector<Layer>& layers);

  void apply_view(ViewPreset view);
  ViewPreset view() const { return view_; }

  const SceneLegend& legend() const { return *legend_; }
  std::vector<ScreenBox> label_boxes() const;  // the visible labels' extents on screen
  // The width and height text (Boundary layer); its input holds the labels the view shows.
  vtkActor2D* dimension_label_actor() const { return dimension_labels_; }

  // Measurement: pick_at() picks the surface drawn under display (x, y) (origin bottom-left; the
  // scene must have been rendered) and adds it to the last measurement, or starts a new one
  // (add_pick); all are drawn in white, each with its distance, until cleared.
  std::optional<Eigen::Vector3d> pick_at(double x, double y);
  const std::vector<Measurement>& measurements() const { return measurements_; }
  // The last measurement (the one being picked); empty when there is none.
  const Measurement& measurement() const;
  void set_measurements(const std::vector<Measurement>& measurements);

  // Number of points / cells currently in a polydata layer (for tests and the status bar).
  vtkIdType layer_size(Layer layer) const;
  // The polydata a layer currently draws (null for axes/legend).
  vtkPolyData* layer_polydata(Layer layer) const;

  // Pixel box (top row = 0) of the map's boundary corners as the current camera projects them
  // into a `width` x `height` image; count 0 when no boundary is detected.
  PixelBox projected_boundary(int width, int height) const;

 private:
  vtkSmartPointer<vtkActor> make_actor(const Rgb* color, double point_size, double line_width,
                                       bool unlit);
  void set_input(Layer layer, vtkPolyData* poly);
  void add_zone_outlines();
  vtkSmartPointer<vtkActor2D> add_labels(const Rgb& color, int font_size);
  void refresh_visibility();

  vtkSmartPointer<vtkRenderer> renderer_;
  std::array<vtkSmartPointer<vtkActor>, kLayerCount> actors_;  // null for axes/legend
  // Opaque outlines of constant screen width over the translucent zone fills.
  vtkSmartPointer<vtkActor> traversable_outline_, forbidden_outline_;
  vtkSmartPointer<vtkActor2D> grid_labels_;       // distances on the floor (Grid layer)
  vtkSmartPointer<vtkActor2D> dimension_labels_;  // width and height (Boundary layer)
  vtkSmartPointer<vtkActor> measurement_actor_;
  vtkSmartPointer<vtkActor2D> measurement_label_;
  std::vector<Measurement> measurements_;
  vtkSmartPointer<vtkAxesActor> axes_;
  std::unique_ptr<SceneLegend> legend_;
  unsigned long fit_observer_ = 0;
  std::array<bool, kLayerCount> visible_;
  ViewPreset view_ = ViewPreset::Reset;
  TunnelMap map_;  // copy of the last map, for the camera presets
  int max_points_ = kDefaultDisplayPoints;
};

}  // namespace tunnelmap::scene
