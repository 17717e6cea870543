#pragma once
// What the scene shows for one frame. Pointers are borrowed: they must outlive the call to
// TunnelScene::update() (the scene copies what it draws into VTK arrays).
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "core/frame/depth_frame.h"
#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap::scene {

struct SceneData {
  const DepthFrame* frame = nullptr;      // colours (RGB) and intrinsics for the frustum
  const OrganizedCloud* cloud = nullptr;  // camera-frame points
  const PlaneSegments* planes = nullptr;  // label image + planes
  const TunnelMap* map = nullptr;         // walls, boundary, zones, plane classes
  vtkSmartPointer<vtkPolyData> mesh;      // fused RGB-D mesh, when another stage provides one
};

}  // namespace tunnelmap::scene
