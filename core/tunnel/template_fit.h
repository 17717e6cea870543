#pragma once
// Step 3 of tunnel detection: the rectangular template. Opposite walls must be antiparallel,
// the two pairs perpendicular; the result is one orthonormal tunnel frame.
#include <Eigen/Core>
#include <string>

#include "core/tunnel/tunnel_status.h"

namespace tunnelmap {

struct TemplateFrame {
  bool ok = false;
  TunnelStatus status = TunnelStatus::Ok;  // else NoParallelPair or NotRectangular
  std::string reason;
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();  // = left wall's normal = -right wall's
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();    // = floor's normal = -roof's
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // along the tunnel, away from the camera
  double left_right_angle_deg = 0.0;  // deviation from antiparallel
  double top_bottom_angle_deg = 0.0;
  double pair_angle_deg = 0.0;        // deviation of the two pair directions from 90 degrees
};

// Inputs: the four class mean normals (unit, inward). `camera_forward` orients the axis.
TemplateFrame fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                                       const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                                       const Eigen::Vector3d& camera_forward,
                                       double max_pair_angle_deg);
// The same, written into `out`: its reason string keeps its buffer, so a caller that
// reuses `out` allocates nothing per frame in the steady state.
void fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                              const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                              const Eigen::Vector3d& camera_forward, double max_pair_angle_deg,
                              TemplateFrame& out);

// With walls out of view: `seen[i]` says whether means[i] (left, right, top, bottom) was
// measured; at least two walls must be. A pair with both walls seen must be antiparallel as
// above; a direction no wall gives comes from the rough frame (`rough_right`, `rough_up`) made
// perpendicular to the measured one. All four seen: the same as fit_rectangular_template.
// `weights` (optional, > 0 for the walls seen): a pair's direction is the weighted mean of its
// two walls' normals, as each wall's normal is the point-weighted mean of its planes' (with
// none, the plain mean); with both pairs seen, each pair's direction gives way to make them
// perpendicular in proportion to the other pair's weight (equal weights: half each).
void fit_partial_template(const Eigen::Vector3d means[4], const bool seen[4],
                          const Eigen::Vector3d& rough_right, const Eigen::Vector3d& rough_up,
                          const Eigen::Vector3d& camera_forward, double max_pair_angle_deg,
                          TemplateFrame& out, const double weights[4] = nullptr);

}  // namespace tunnelmap
