#pragma once
// The girder's centre line from a posed sequence: each frame that measured all four walls gives
// the centre of its cross-section at the camera's station and the girder's axis and up there
// (its detection, moved into the world by its pose). A smooth curve is fitted through these
// centres (a local quadratic per node, over a window along the girder), and its arc length is
// the station. A curve of radius R departs from a quadratic by about d^3 / (6 R^2) at distance d,
// under 0.2 mm over a 3 m half-window on R = 150 m, while the window averages the frames' centre
// noise; a chain of straight compartments is followed to within its chords' sagitta.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/mapping/centreline.h"
#include "core/mapping/map_options.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// One frame's view of the centre line, world frame.
struct CentreSample {
  Eigen::Vector3d point;  // the cross-section's centre at the camera's station
  Eigen::Vector3d axis;   // unit, sign as the frame's detection gives it
  Eigen::Vector3d up;     // unit
};

// The frames (in order) that measured both wall pairs, with `poses[i]` their camera-to-world.
std::vector<CentreSample> centre_samples(const std::vector<TunnelMap>& maps,
                                         const std::vector<Eigen::Isometry3d>& poses);

// The fitted line, stations counted from `origin` (its station is 0) and growing along
// `forward` (the first frame's view). None when the samples span less than two windows
// (`options.centreline_window_m` each side): over such a stretch the straight axis of one
// frame is as good.
std::optional<Centreline> fit_centreline(const std::vector<CentreSample>& samples, const Eigen::Vector3d& origin,
                                         const Eigen::Vector3d& forward, const StationMapOptions& options);

}  // namespace tunnelmap
