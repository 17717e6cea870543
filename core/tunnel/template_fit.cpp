#include "core/tunnel/template_fit.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "core/tunnel/normal_outliers.h"

namespace tunnelmap {

namespace {
// snprintf into `out`, reusing its buffer (a returned std::string would allocate every time).
void set_text(std::string& out, const char* f, double a, double b) {
  char buf[200];
  std::snprintf(buf, sizeof buf, f, a, b);
  out.assign(buf);
}
}  // namespace

TemplateFrame fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                                       const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                                       const Eigen::Vector3d& camera_forward,
                                       double max_pair_angle_deg) {
  TemplateFrame t;
  fit_rectangular_template(n_left, n_right, n_top, n_bottom, camera_forward, max_pair_angle_deg, t);
  return t;
}

void fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                              const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                              const Eigen::Vector3d& camera_forward, double max_pair_angle_deg,
                              TemplateFrame& t) {
  {  // Default values in every field, but the strings keep their buffers.
    TemplateFrame fresh;
    fresh.status.swap(t.status);
    fresh.reason.swap(t.reason);
    fresh.status.clear();
    fresh.reason.clear();
    t = std::move(fresh);
  }
  t.left_right_angle_deg = angle_deg(n_left, -n_right);
  t.top_bottom_angle_deg = angle_deg(n_bottom, -n_top);
  if (t.left_right_angle_deg > max_pair_angle_deg) {
    t.status = "no_parallel_pair";
    set_text(t.reason, "left and right walls are %.1f deg from parallel (max %.1f)",
             t.left_right_angle_deg, max_pair_angle_deg);
    return;
  }
  if (t.top_bottom_angle_deg > max_pair_angle_deg) {
    t.status = "no_parallel_pair";
    set_text(t.reason, "top and bottom walls are %.1f deg from parallel (max %.1f)",
             t.top_bottom_angle_deg, max_pair_angle_deg);
    return;
  }
  // One direction per pair; both walls of a pair contribute equally.
  const Eigen::Vector3d a = (n_left - n_right).normalized();
  const Eigen::Vector3d b = (n_bottom - n_top).normalized();
  t.pair_angle_deg = std::abs(angle_deg(a, b) - 90.0);
  if (t.pair_angle_deg > max_pair_angle_deg) {
    t.status = "not_rectangular";
    set_text(t.reason, "wall pairs are %.1f deg from perpendicular (max %.1f)", t.pair_angle_deg,
             max_pair_angle_deg);
    return;
  }
  // Orthogonalise symmetrically: rotate a and b by half the error each, about their bisector.
  const Eigen::Vector3d s = (a + b).normalized();
  const Eigen::Vector3d d = (a - b).normalized();
  t.right = (s + d).normalized();
  t.up = (s - d).normalized();
  t.axis = t.up.cross(t.right);
  if (t.axis.dot(camera_forward) < 0) t.axis = -t.axis;
  t.ok = true;
}

}  // namespace tunnelmap
