#pragma once
// Geometry of the fitted tunnel map: wall boundary rectangles (lines) and zone rectangles
// (polygons). Both are lifted 15-20 mm off the wall, into the tunnel, so they are not
// hidden by the wall's own points.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

vtkSmartPointer<vtkPolyData> make_boundary_polydata(const TunnelMap& map);
vtkSmartPointer<vtkPolyData> make_zones_polydata(const TunnelMap& map, ZoneKind kind);

}  // namespace tunnelmap::scene
