#pragma once
// A mesh in the world frame (a loaded mesh PLY, or the fused mesh) drawn in the 3D view, which
// shows the current frame's camera frame: a posed frame moves the mesh by its pose, so the
// mesh is placed again whenever another frame is shown.
#include <string>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/mesh_level_of_detail.h"

namespace tunnelmap::scene {
struct ProcessedFrame;
}

namespace tunnelmap::ui {

class View3DWidget;

// A triangle mesh PLY as polydata, a long one cut into pieces (`progress`: as they are cut, false
// cancels and gives null); InputError(file, problem) for a bad file, one without vertices or one
// without faces (a point cloud is not a mesh). Safe on a worker thread.
vtkSmartPointer<vtkPolyData> read_mesh_ply(const std::string& file, const PieceProgress& progress = {});

class MeshOverlay {
 public:
  explicit MeshOverlay(View3DWidget* view) : view_(view) {}

  // Shows `world_mesh` for the frame shown now (`frame` -1: none), or clears the layer.
  void show(vtkSmartPointer<vtkPolyData> world_mesh, const scene::ProcessedFrame* shown, int frame);
  // The mesh is already in the view (the fused scene draws it): only remember it and its frame.
  void adopt(vtkSmartPointer<vtkPolyData> world_mesh, int frame);
  // After another frame is shown: placed again by that frame's pose.
  void follow(const scene::ProcessedFrame* shown, int frame);
  void forget_placement() { placed_for_ = -1; }

 private:
  View3DWidget* view_;
  vtkSmartPointer<vtkPolyData> world_mesh_;
  int placed_for_ = -1;  // frame whose pose placed the shown mesh
};

}  // namespace tunnelmap::ui
