#pragma once
// Qhull baseline (paper section 3, Barber et al. 1996; MATLAB convhulln in the paper): the
// convex hull of the frame's points, then an axial alignment: the tunnel axis is the direction
// (near the camera's view, perpendicular to up within a tilt range) along which the hull's
// cross-section bounding rectangle is smallest; its sides give width and height. No planes.
#include <Eigen/Core>

#include "core/frame/organized_cloud.h"
#include "core/baselines/baseline_options.h"  // QhullOptions
#include "core/tunnel/tunnel_detector.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct QhullTunnelResult {
  TunnelMap map;
  int hull_vertices = 0;
  int input_points = 0;
};

// The template window (width/height min/max) and the context tolerance of `tunnel` are
// applied like for PG&C, so detection rates are comparable. Runs qhull ("qhull Qt").
QhullTunnelResult qhull_tunnel(const OrganizedCloud& cloud, const Eigen::Vector3d& up_camera,
                               const TunnelOptions& tunnel, const TunnelContext* context,
                               const QhullOptions& options = QhullOptions());

}  // namespace tunnelmap
