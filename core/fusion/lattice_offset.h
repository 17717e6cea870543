#pragma once
// Where the sparse lattice's origin goes: the walls of the merged map as near the middle of
// their blocks as they allow. A frame's truncation band (+-fusion.truncation_mm along each ray)
// around a wall in the middle of a block layer stays in that layer, around a wall near a block
// boundary it allocates two; the same girder moved half a block sideways cost 1.43 x the blocks
// (docs/fusion.md).
#include <Eigen/Core>

#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// The world position of voxel (0, 0, 0)'s centre: the lattice turned by `lattice_to_world` and
// moved by less than a block along each of its axes that some found wall of `merged` (world
// frame) lies across (within 1 deg); zero without such walls.
Eigen::Vector3d wall_centred_origin(const TunnelMap& merged, const Eigen::Matrix3d& lattice_to_world, double voxel_m);

}  // namespace tunnelmap
