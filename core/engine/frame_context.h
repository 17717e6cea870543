#pragma once
// The context rule, the same for every front end: a posed frame takes its context from the
// station map along the tunnel (world frame, follows sections that change); a frame without a
// pose from the widths of the recent frames. Applied in frame order, after the frame's own
// detection, so detection itself may run on several threads.
#include <optional>

#include "core/mapping/station_map_builder.h"
#include "core/pipeline/pipeline.h"
#include "core/tunnel/tunnel_detector.h"

namespace tunnelmap {

class FrameContext {
 public:
  explicit FrameContext(const Parameters& params);

  // Frame `index`'s result (detected without context) gets the context of the frames before it,
  // then becomes part of the context of the frames after it.
  void apply(int index, FrameResult& result, const std::optional<Eigen::Isometry3d>& pose);

  // For a method that checks the context inside its own fit (the convex-hull baseline).
  TunnelContext& recent() { return recent_; }
  const StationMapBuilder& stations() const { return stations_; }

 private:
  TunnelOptions tunnel_;
  TunnelContext recent_;
  StationMapBuilder stations_;
};

}  // namespace tunnelmap
