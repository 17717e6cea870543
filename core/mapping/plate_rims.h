#pragma once
// The rims of openings in the plates across the tunnel (a diaphragm's manhole): where a plate's
// pixels end and the view passes through to something much farther. Kept per frame beside its
// wall samples, so the map can fit each manhole from every frame that looked through it.
#include <vector>

#include "core/mapping/frame_walls.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

// Rim points of the planes `plate_ids` of `r` (camera frame, on each plate's fitted plane),
// appended to `out`; at most o.max_rim_points_per_plate per plate, spread over its rim.
void extract_plate_rims(const FrameResult& r, const std::vector<int>& plate_ids,
                        const FrameWallsOptions& o, std::vector<RimPoint>& out);

}  // namespace tunnelmap
