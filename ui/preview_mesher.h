#pragma once
// The worker side of the fused view's growing mesh (ui/fusion_preview.h), free of Qt: after a
// frame is integrated, decides whether the volume is meshed again, re-extracts only the chunks
// the frames since the last preview touched (IncrementalMesher) and hands the snapshot on,
// converted by the final mesh's converter (fused_mesh_polydata).
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "mesh/sparse_mesher.h"

namespace tunnelmap::ui {

// No sooner after a preview than this many times what it cost, making it on the worker and
// drawing it on the GUI thread (both take the cores the integration uses): previews then take
// at most a fifth of the time however large the volume grows or slow the renderer is.
constexpr int kPreviewCostFactor = 4;

// Between the worker and the view showing its snapshots.
struct PreviewChannel {
  std::atomic<bool> in_flight{false};  // delivered, not shown yet: no new snapshot meanwhile
  std::atomic<int> show_ms{0};         // what showing the last one cost the GUI thread
};

struct PreviewMesh {
  vtkSmartPointer<vtkPolyData> mesh;  // world frame
  long long triangles = 0;
  int done = 0, total = 0;  // frames integrated
  double worker_ms = 0.0;   // what making it cost the fusion (update, merge, conversion)
};

class PreviewMesher {
 public:
  using Deliver = std::function<void(PreviewMesh)>;
  // Whoever shows a snapshot clears `channel->in_flight` and sets its `show_ms`.
  PreviewMesher(int min_weight, std::chrono::milliseconds interval, std::shared_ptr<PreviewChannel> channel,
                Deliver deliver);
  // Between frames, on the fusing thread. Nothing after the last frame: the final mesh follows
  // (extracted from scratch as without previews, so it is the same mesh).
  void after_frame(const SparseTsdfVolume& volume, int done, int total);

 private:
  bool due() const;

  using Clock = std::chrono::steady_clock;
  int min_weight_;
  IncrementalMesher mesher_;
  std::chrono::milliseconds interval_;
  std::shared_ptr<PreviewChannel> channel_;
  Deliver deliver_;
  bool first_ = true;  // the first mesh at once: the view changes as soon as it can
  Clock::time_point last_;        // when the last snapshot was delivered
  Clock::duration last_cost_{};  // what making it cost
};

}  // namespace tunnelmap::ui
