#pragma once
// The 3D view's mesh layer: a mesh PLY file as VTK polydata, and a world-frame mesh moved into
// the camera frame of the shown frame.
#include <Eigen/Geometry>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/io/ply_mesh_reader.h"
#include "ui/mesh_level_of_detail.h"

namespace tunnelmap::ui {

// Points, triangles and vertex colours through scene::mesh_polydata (the converter the fused
// scene uses for its TSDF mesh), plus the file's normals when it has them. A long mesh comes
// back as its decimated overview carrying its pieces (ui/mesh_level_of_detail.h).
// Null when `progress` (ui/mesh_level_of_detail.h) cancelled the cutting.
vtkSmartPointer<vtkPolyData> ply_mesh_polydata(const PlyMesh& mesh, const PieceProgress& progress = {});

// `world_mesh` with every point mapped by `world_to_camera`; normals dropped (world-frame
// normals would light it wrongly). Shares the cells and colours of `world_mesh`. A long mesh's
// pieces near the camera at full resolution and the others decimated.
vtkSmartPointer<vtkPolyData> mesh_in_camera_frame(vtkPolyData* world_mesh, const Eigen::Isometry3d& world_to_camera);

}  // namespace tunnelmap::ui
