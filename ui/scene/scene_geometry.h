#pragma once
// SceneGeometry: every polydata the scene shows for one frame, built apart from the scene so a
// worker thread can build it while the GUI thread keeps drawing the previous frame; the GUI
// thread then only swaps mapper inputs (TunnelScene::set_geometry) and renders.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/scene/scene_data.h"

namespace tunnelmap::scene {

// Point layers are decimated to at most this many grid pixels each (stride 3 for VGA): a
// software renderer spends its time per drawn point (see cloud_polydata.h).
constexpr int kDefaultDisplayPoints = 40000;

struct GeometryOptions {
  int max_points = kDefaultDisplayPoints;  // per point layer; <= 0: full density
  bool cloud = true;                       // false: leave `cloud` null (keep the shown layer)
};

struct SceneGeometry {
  vtkSmartPointer<vtkPolyData> cloud;  // null: the scene keeps its current cloud layer
  vtkSmartPointer<vtkPolyData> planes, boundary, traversable, forbidden, frustum;
  // The distance grid on the floor and its labels (station_grid.h); null: none.
  vtkSmartPointer<vtkPolyData> grid, grid_labels;
  vtkSmartPointer<vtkPolyData> mesh;  // null: the scene keeps its current mesh layer
  TunnelMap map;                      // for the camera presets
  int stride = 1;                     // point-layer decimation used (sets the point size)
};

SceneGeometry build_geometry(const SceneData& data, const GeometryOptions& options = {});

}  // namespace tunnelmap::scene
