#pragma once
// A map mesh PLY (core/export/map_ply.h: coloured triangles labelled by wall) as tunnelmap-render
// shows it: the triangles with their vertex colours, plus the tunnel frame the camera presets
// need (axis, up, extent, size), recovered from the walls' positions in the mesh.
#include <string>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::render {

struct MapMesh {
  vtkSmartPointer<vtkPolyData> poly;      // every triangle but the boundary bands
  vtkSmartPointer<vtkPolyData> boundary;  // the boundary bands (label Boundary); may be empty
  // detected, axis_point (the mesh's centre), axis_dir, up, extent along the axis, width and
  // height across it; no walls or zones (the mesh draws those).
  TunnelMap frame;
  std::size_t triangles = 0;
};

// True for a ".ply" file name (any case): the input is a mesh, not a depth frame or dataset.
bool is_mesh_input(const std::string& path);

// Reads the PLY with the project's strict reader; InputError naming the file when it cannot be
// read or has no triangles. `cutaway` leaves out the roof and the right wall (faces whose `wall`
// says so), so that a camera above the right wall sees the floor, the left wall and the plates
// with their manholes inside; the frame is still that of the whole mesh.
MapMesh load_map_mesh(const std::string& path, bool cutaway = false);

}  // namespace tunnelmap::render
