#pragma once
// Point-cloud layers as vtkPolyData with per-point RGB colours (direct scalars). Both keep one
// pixel in `stride` along each image axis: a software renderer (llvmpipe under Xvfb, OSMesa)
// spends its time per drawn point, and a VGA frame shown in a few hundred screen pixels looks
// the same at stride 2-3 with slightly larger points.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/scene/scene_data.h"

namespace tunnelmap::scene {

// All valid points; coloured by the frame's RGB when present, else by depth (viridis-like).
vtkSmartPointer<vtkPolyData> make_cloud_polydata(const SceneData& data, int stride = 1);

// Points that belong to a plane, coloured by the wall class of their plane (outliers and
// planes without a class: "unassigned").
vtkSmartPointer<vtkPolyData> make_planes_polydata(const SceneData& data, int stride = 1);

// The smallest stride that keeps at most `max_points` of a width x height grid (>= 1;
// max_points <= 0 means full density).
int display_stride(int width, int height, int max_points);

}  // namespace tunnelmap::scene
