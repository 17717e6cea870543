#pragma once
// Time pairing of a TUM sequence's streams: depth frames with colour images (nearest timestamp,
// as TUM's associate.py) and with the ground-truth trajectory (interpolated).
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/io/tum_list.h"

namespace tunnelmap {

// For each query time, the index of its candidate or -1. Pairs at most `max_dt` apart are taken
// closest first, each candidate at most once (associate.py's greedy rule); equal gaps go to the
// earlier query, then the earlier candidate. Both lists sorted increasing.
std::vector<int> associate_nearest(const std::vector<double>& queries,
                                   const std::vector<double>& candidates, double max_dt);

// Camera-to-world pose at time t: between the two bracketing samples, linear in translation and
// slerp in rotation (a sample's own time gives that sample exactly). Before the first or after
// the last sample, that end's pose if it is at most `max_dt` away, else none (no extrapolation).
// `samples` sorted strictly increasing; none if empty.
std::optional<Eigen::Isometry3d> interpolate_pose(const std::vector<TumPoseEntry>& samples, double t,
                                                  double max_dt);

}  // namespace tunnelmap
