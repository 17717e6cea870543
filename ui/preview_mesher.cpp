#include "ui/preview_mesher.h"

#include <algorithm>

#include "ui/fused_scene.h"

namespace tunnelmap::ui {

PreviewMesher::PreviewMesher(int min_weight, std::chrono::milliseconds interval,
                             std::shared_ptr<PreviewChannel> channel, Deliver deliver)
    : min_weight_(min_weight),
      mesher_(min_weight),
      interval_(interval),
      channel_(std::move(channel)),
      deliver_(std::move(deliver)) {}

bool PreviewMesher::due() const {
  if (channel_->in_flight.load()) return false;
  if (first_) return true;
  const auto cost = last_cost_ + std::chrono::milliseconds(channel_->show_ms.load());
  return Clock::now() >= last_ + std::max<Clock::duration>(interval_, kPreviewCostFactor * cost);
}

void PreviewMesher::after_frame(const SparseTsdfVolume& volume, int done, int total) {
  if (done >= total) {
    mesher_ = IncrementalMesher(min_weight_);  // its chunks, a mesh's worth, freed before the final mesh
    return;
  }
  if (!due()) return;
  const auto start = Clock::now();
  mesher_.update(volume);
  const TriangleMesh mesh = mesher_.mesh();
  if (mesh.triangles.empty()) return;  // fusion.min_weight frames have not met yet: try the next
  PreviewMesh p{fused_mesh_polydata(mesh), static_cast<long long>(mesh.triangles.size()), done, total};
  last_ = Clock::now();
  last_cost_ = last_ - start;
  p.worker_ms = std::chrono::duration<double, std::milli>(last_cost_).count();
  first_ = false;
  channel_->in_flight.store(true);
  deliver_(std::move(p));
}

}  // namespace tunnelmap::ui
