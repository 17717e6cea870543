#include "ui/scene/camera_presets.h"

#include <Eigen/Geometry>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace tunnelmap::scene {

const char* view_name(ViewPreset v) {
  switch (v) {
    case ViewPreset::Along: return "along";
    case ViewPreset::Side: return "side";
    case ViewPreset::Top: return "top";
    case ViewPreset::Reset: return "reset";
    case ViewPreset::Oblique: return "oblique";
  }
  return "?";
}

ViewPreset parse_view(const std::string& name) {
  for (ViewPreset v : {ViewPreset::Along, ViewPreset::Side, ViewPreset::Top, ViewPreset::Reset,
                       ViewPreset::Oblique})
    if (name == view_name(v)) return v;
  throw std::invalid_argument("unknown view '" + name + "' (along, side, top, reset, oblique)");
}

namespace {

// Corners of the box to frame: the map's tunnel box when detected, else the visible props'
// bounds.
std::vector<Eigen::Vector3d> box_corners(vtkRenderer* renderer, const TunnelMap& map) {
  std::vector<Eigen::Vector3d> corners;
  if (map.detected && map.extent_max_m > map.extent_min_m) {
    const Eigen::Vector3d axis = map.axis_dir.normalized(), up = map.up.normalized();
    const Eigen::Vector3d side = up.cross(axis).normalized();
    for (double a : {map.extent_min_m, map.extent_max_m})
      for (double s : {-0.5, 0.5})
        for (double u : {-0.5, 0.5})
          corners.push_back(map.axis_point + a * axis + s * map.width_m * side + u * map.height_m * up);
    return corners;
  }
  double b[6];
  renderer->ComputeVisiblePropBounds(b);
  if (!(b[0] <= b[1])) return corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)]);
  return corners;
}

}  // namespace

void fit_view_to_map(vtkRenderer* renderer, const TunnelMap& map) {
  const std::vector<Eigen::Vector3d> corners = box_corners(renderer, map);
  if (corners.empty() || !renderer->GetRenderWindow()) return;
  vtkCamera* cam = renderer->GetActiveCamera();
  for (int pass = 0; pass < 3; ++pass) {
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    for (const auto& c : corners) {
      renderer->SetWorldPoint(c.x(), c.y(), c.z(), 1.0);
      renderer->WorldToView();
      double v[3];
      renderer->GetViewPoint(v);
      for (int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], v[k]);
        hi[k] = std::max(hi[k], v[k]);
      }
    }
    const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(extent > 1e-6)) return;
    // Move the camera sideways so the box's projected centre lands in the middle...
    double focal[3], pos[3], up[3];
    cam->GetFocalPoint(focal);
    cam->GetPosition(pos);
    cam->GetViewUp(up);
    const Eigen::Vector3d f(focal[0], focal[1], focal[2]), p(pos[0], pos[1], pos[2]);
    const Eigen::Vector3d u = Eigen::Vector3d(up[0], up[1], up[2]).normalized();
    const Eigen::Vector3d r = (f - p).normalized().cross(u).normalized();
    const double half_h = (f - p).norm() * std::tan(0.5 * cam->GetViewAngle() * 3.14159265358979 / 180.0);
    const double aspect = renderer->GetTiledAspectRatio();
    const Eigen::Vector3d shift = r * (0.5 * (lo[0] + hi[0]) * half_h * aspect) + u * (0.5 * (lo[1] + hi[1]) * half_h);
    const Eigen::Vector3d nf = f + shift, np = p + shift;
    cam->SetFocalPoint(nf.x(), nf.y(), nf.z());
    cam->SetPosition(np.x(), np.y(), np.z());
    // ...then zoom so its larger side spans 90 % of the view (view coordinates run -1..1).
    cam->Zoom(0.9 * 2.0 / std::max(hi[0] - lo[0], hi[1] - lo[1]));
  }
  renderer->ResetCameraClippingRange();
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
    case ViewPreset::Oblique:  // from above the right wall, a little behind the start
      dir = (0.55 * axis + 0.65 * side - 0.52 * up).normalized();
      break;
  }
  vtkCamera* cam = renderer->GetActiveCamera();
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(-dir.x(), -dir.y(), -dir.z());
  cam->SetViewUp(view_up.x(), view_up.y(), view_up.z());
  cam->SetViewAngle(45.0);
  renderer->ResetCamera();  // keeps the direction, fits the visible props
  if (view == ViewPreset::Oblique) fit_view_to_map(renderer, map);
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
