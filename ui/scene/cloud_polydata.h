#pragma once
// Point-cloud layers as vtkPolyData with per-point RGB colours (direct scalars).
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "ui/scene/scene_data.h"

namespace tunnelmap::scene {

// All valid points; coloured by the frame's RGB when present, else by depth (viridis-like).
vtkSmartPointer<vtkPolyData> make_cloud_polydata(const SceneData& data);

// Points that belong to a plane, coloured by the wall class of their plane (outliers and
// planes without a class: "unassigned").
vtkSmartPointer<vtkPolyData> make_planes_polydata(const SceneData& data);

}  // namespace tunnelmap::scene
