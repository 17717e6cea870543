#include "ui/mesh_overlay.h"

#include "core/io/ply_mesh_reader.h"
#include "core/util/error.h"
#include "ui/mesh_layer.h"
#include "ui/scene/processed_frame.h"
#include "ui/view3d_widget.h"

namespace tunnelmap::ui {

vtkSmartPointer<vtkPolyData> read_mesh_ply(const std::string& file, const PieceProgress& progress) {
  const PlyMesh ply = read_ply_mesh(file);  // InputError(file, problem) on any bad input
  if (ply.vertices.empty()) throw InputError(file, "PLY has no vertices");
  if (ply.triangles.empty()) throw InputError(file, "PLY has no faces (not a mesh)");
  return ply_mesh_polydata(ply, progress);
}

void MeshOverlay::show(vtkSmartPointer<vtkPolyData> world_mesh, const scene::ProcessedFrame* shown, int frame) {
  world_mesh_ = world_mesh;
  placed_for_ = shown ? frame : -1;
  if (!world_mesh_) return view_->set_mesh(nullptr);
  // The scene is in the shown frame's camera frame; a posed frame maps world -> camera.
  if (!shown || !shown->frame.pose) return view_->set_mesh(world_mesh_);
  view_->set_mesh(mesh_in_camera_frame(world_mesh_, shown->frame.pose->inverse()));
}

void MeshOverlay::adopt(vtkSmartPointer<vtkPolyData> world_mesh, int frame) {
  world_mesh_ = world_mesh;
  placed_for_ = frame;
}

void MeshOverlay::follow(const scene::ProcessedFrame* shown, int frame) {
  // Without a mesh of its own the layer is still cleared once: another view (a fusion's
  // growing mesh) may have left its mesh there.
  if (frame != placed_for_) show(world_mesh_, shown, frame);
}

}  // namespace tunnelmap::ui
