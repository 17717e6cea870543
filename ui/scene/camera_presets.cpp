#include "ui/scene/camera_presets.h"

#include <Eigen/Geometry>
#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tunnelmap::scene {

const char* view_name(ViewPreset v) {
  switch (v) {
    case ViewPreset::Along: return "along";
    case ViewPreset::Side: return "side";
    case ViewPreset::Top: return "top";
    case ViewPreset::Reset: return "reset";
  }
  return "?";
}

ViewPreset parse_view(const std::string& name) {
  for (ViewPreset v : {ViewPreset::Along, ViewPreset::Side, ViewPreset::Top, ViewPreset::Reset})
    if (name == view_name(v)) return v;
  throw std::invalid_argument("unknown view '" + name + "' (along, side, top, reset)");
}

void apply_view(vtkRenderer* renderer, ViewPreset view, const TunnelMap& map) {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();
  if (map.detected && map.axis_dir.allFinite() && map.up.allFinite() && map.axis_dir.norm() > 0.5 &&
      map.up.norm() > 0.5) {
    axis = map.axis_dir.normalized();
    up = (map.up - map.up.dot(axis) * axis).normalized();  // exactly perpendicular to the axis
  }
  const Eigen::Vector3d side = up.cross(axis).normalized();  // camera frame: +x for the defaults
  Eigen::Vector3d dir = axis;  // direction of projection
  Eigen::Vector3d view_up = up;
  switch (view) {
    case ViewPreset::Along:
    case ViewPreset::Reset: break;
    case ViewPreset::Side: dir = side; break;        // looking across the tunnel
    case ViewPreset::Top: dir = -up; view_up = axis; break;  // looking down, tunnel pointing up
  }
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(-dir.x(), -dir.y(), -dir.z());
  cam->SetViewUp(view_up.x(), view_up.y(), view_up.z());
  cam->SetViewAngle(45.0);
  renderer->ResetCamera();  // keeps the direction, fits the visible props
  if (view == ViewPreset::Along && !map.detected) cam->Zoom(1.6);  // fitted box is loose
  if (view == ViewPreset::Along && map.detected && map.extent_max_m > map.extent_min_m) {
    // Stand on the axis just before the visible part, far enough back that the tunnel's
    // cross-section fills the view: a person looking into the tunnel.
    const double half = 0.5 * std::max(map.width_m, map.height_m);
    const double back = 1.1 * half / std::tan(0.5 * 45.0 * 3.14159265358979 / 180.0);
    const Eigen::Vector3d start = map.axis_point + axis * map.extent_min_m;
    const Eigen::Vector3d eye = start - axis * back;
    const Eigen::Vector3d focal = map.axis_point + axis * map.extent_max_m;
    cam->SetPosition(eye.x(), eye.y(), eye.z());
    cam->SetFocalPoint(focal.x(), focal.y(), focal.z());
    cam->SetViewUp(view_up.x(), view_up.y(), view_up.z());
  }
  renderer->ResetCameraClippingRange();
}

}  // namespace tunnelmap::scene
