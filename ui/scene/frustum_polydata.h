#pragma once
// The depth camera's viewing frustum (camera frame, apex at the origin) as lines.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/frame/intrinsics.h"

namespace tunnelmap::scene {

vtkSmartPointer<vtkPolyData> make_frustum_polydata(const Intrinsics& k, double depth_m);

}  // namespace tunnelmap::scene
