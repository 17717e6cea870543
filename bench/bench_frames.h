#pragma once
// The VGA frames every benchmark runs on: simulated lab and field frames (in memory, fixed
// seeds) and the real third-party frames in resources/real-frames.
#include <cstdint>
#include <string>
#include <vector>

#include "core/frame/depth_frame.h"

namespace tunnelmap::bench {

struct NamedFrame {
  std::string name;
  DepthFrame frame;
  bool is_tunnel;  // a rectangular tunnel the detector should find
  // Simulated frames only: per-pixel true surface normal in the camera frame (NaN where the
  // pixel sees no planar surface), for normal-quality counters.
  std::vector<Eigen::Vector3f> true_normals;
  // Simulated frames only: the simulator's per-pixel true surface id (0 = nothing), for
  // plane recall/precision (core/evaluation/segmentation_metrics.h). Empty for real frames.
  std::vector<std::uint16_t> surface_id;
};

const std::vector<NamedFrame>& bench_frames();

}  // namespace tunnelmap::bench
