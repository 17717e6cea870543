#include "core/engine/frame_context.h"

#include "core/mapping/map_options.h"

namespace tunnelmap {

FrameContext::FrameContext(const Parameters& params)
    : tunnel_(tunnel_options(params)), stations_(station_map_options(params), tunnel_) {}

void FrameContext::apply(int index, FrameResult& result, const std::optional<Eigen::Isometry3d>& pose) {
  if (pose) {
    stations_.add_frame(index, result, *pose);
    return;
  }
  apply_tunnel_context(result.map, tunnel_, recent_);
  if (result.map.detected) recent_.accept(result.map);
}

}  // namespace tunnelmap
