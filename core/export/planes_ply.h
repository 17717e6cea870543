#pragma once
// Writes the points of the segmented planes as a binary PLY point cloud coloured by wall class.
#include <string>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// One vertex per pixel that belongs to a plane and has a valid point: x y z (float),
// red green blue (uchar), plane (int, PlaneSegment::id). `classes` is per PlaneSegment in
// `planes.planes` order (missing entries count as unassigned). Colours: left blue, right green,
// top yellow, bottom magenta, unassigned grey. Written atomically; InputError on failure.
void write_planes_ply(const std::string& path, const OrganizedCloud& cloud, const PlaneSegments& planes,
                      const std::vector<WallClass>& classes);

}  // namespace tunnelmap
