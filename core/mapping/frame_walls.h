#pragma once
// A frame's wall points in compact form: per plane, the mean of its pixels in each 8 x 8 pixel
// block (camera frame), with the wall it measures. Small enough to keep for every frame of a
// sequence (a few thousand samples), and enough to rebuild the station map, or to align the
// frame with the map, under other camera poses without the frame's images.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/pipeline/pipeline.h"

namespace tunnelmap {

// Walls 0-3 are WallClass Left..Bottom; kTransverseSample marks a plane across the tunnel axis
// (a manhole plate, the step between two sections).
constexpr std::uint8_t kTransverseSample = 4;

struct WallSample {
  Eigen::Vector3f point = Eigen::Vector3f::Zero();  // mean of the block's pixels, camera frame
  int points = 0;
  int plane = 0;               // plane id (label) in the frame
  std::uint8_t wall = 0;       // 0-3: measured wall; kTransverseSample
  float inset_m = 0.0f;        // how far the plane lies inside its wall's outer surface in this
                               // frame (the middle plate: its thickness; an edge band: ~0)
};

struct FrameWalls {
  std::vector<WallSample> samples;
};

// The samples of `r` (its map must come from r.planes). Planes of walls the frame measured,
// edge-on planes excepted, and planes across the axis of at least `min_transverse_points`.
void extract_frame_walls(const FrameResult& r, FrameWalls& out, int block_px = 8,
                         int min_transverse_points = 300);

}  // namespace tunnelmap
