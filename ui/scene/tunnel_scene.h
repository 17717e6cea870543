#pragma once
// TunnelScene: the VTK scene of one processed frame, one actor per layer. It owns a renderer
// that the caller adds to any render window: the Qt widget in the GUI, an OSMesa-backed window
// in tunnelmap-render. No Qt here, so both executables share exactly this code.
#include <array>
#include <vector>

#include <vtkActor.h>
#include <vtkLegendBoxActor.h>
#include <vtkAxesActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "ui/scene/camera_presets.h"
#include "ui/scene/scene_colors.h"
#include "ui/scene/scene_data.h"
#include "ui/scene/scene_layers.h"

namespace tunnelmap::scene {

class TunnelScene {
 public:
  TunnelScene();

  vtkRenderer* renderer() const { return renderer_; }

  // Rebuilds the layers from `data` (pointers need only live during the call). With
  // `rebuild_cloud` false the point-cloud layer is kept (its input did not change).
  void update(const SceneData& data, bool rebuild_cloud = true);
  void clear();

  void set_layer_visible(Layer layer, bool visible);
  bool layer_visible(Layer layer) const { return visible_[static_cast<int>(layer)]; }
  void show_only(const std::vector<Layer>& layers);

  void apply_view(ViewPreset view) { scene::apply_view(renderer_, view, map_); }

  // Number of points / cells currently in a polydata layer (for tests and the status bar).
  vtkIdType layer_size(Layer layer) const;

 private:
  vtkSmartPointer<vtkActor> make_actor(const Rgb* color, double point_size, double line_width,
                                       bool unlit);
  void set_input(Layer layer, vtkPolyData* poly);
  void build_legend();

  vtkSmartPointer<vtkRenderer> renderer_;
  std::array<vtkSmartPointer<vtkActor>, kLayerCount> actors_;  // null for axes/legend
  vtkSmartPointer<vtkAxesActor> axes_;
  vtkSmartPointer<vtkLegendBoxActor> legend_;
  std::array<bool, kLayerCount> visible_;
  TunnelMap map_;  // copy of the last map, for the camera presets
};

}  // namespace tunnelmap::scene
