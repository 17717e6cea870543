#pragma once
// Pipeline: runs the stages in order on one frame, each stage timing itself. Results of earlier
// stages are kept so a parameter change re-runs only the stages from the one it affects.
#include <memory>
#include <optional>

#include "core/frame/depth_frame.h"
#include "core/frame/organized_cloud.h"
#include "core/params/parameters.h"
#include "core/pipeline/frame_scratch.h"
#include "core/planes/plane_segment.h"
#include "core/normals/cloud_builder.h"
#include "core/normals/integral_normals.h"
#include "core/planes/plane_growing.h"
#include "core/tunnel/tunnel_detector.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

// Options derived from Parameters (the table is the single source of truth).
CloudOptions cloud_options(const Parameters& p);
NormalOptions normal_options(const Parameters& p);
GrowOptions grow_options(const Parameters& p);
TunnelOptions tunnel_options(const Parameters& p);

// The "up" direction (towards the roof) in the camera frame, by precedence: world up through
// the frame's pose; else the user's camera-frame vector; else image-up (-Y).
Eigen::Vector3d resolve_up(const DepthFrame& frame, const Eigen::Vector3d& world_up,
                           const std::optional<Eigen::Vector3d>& camera_up);

// InputError naming frame.source when the frame is narrower or lower than the normal window
// (normals.smoothing_px): no pixel of such a frame can get a normal, so it is refused before
// any stage runs instead of giving an empty "result". Allocates nothing when the frame fits.
void check_frame_size(const DepthFrame& frame, const NormalOptions& normals);

struct FrameResult {
  OrganizedCloud cloud;
  PlaneSegments planes;
  TunnelMap map;
  StageTimings timings_ms;  // "cloud", "normals", "planes", "tunnel", "total"
  // The stages' buffers for the next run into this result (not part of its value: copies and
  // moves leave it behind). A result reused frame after frame thus allocates nothing.
  FrameScratch scratch;
};

class Pipeline {
 public:
  explicit Pipeline(Parameters params = Parameters());

  const Parameters& params() const { return params_; }
  void set_params(const Parameters& params);
  void set_world_up(const Eigen::Vector3d& up) { world_up_ = up.normalized(); }
  void set_camera_up(const std::optional<Eigen::Vector3d>& up) { camera_up_ = up; }
  const std::optional<Eigen::Vector3d>& camera_up() const { return camera_up_; }

  // Runs everything from stage `from` on. Stages before `from` reuse `result`'s contents,
  // which must come from an earlier run on the same frame. A frame smaller than the normal
  // window is an InputError (check_frame_size), thrown before `result` is touched. The stages
  // work in result.scratch. Thread-safe (const): concurrent runs need distinct results.
  void run(const DepthFrame& frame, FrameResult& result, TunnelContext* context = nullptr,
           Stage from = Stage::Cloud) const {
    run(frame, result, result.scratch, context, from);
  }
  // The same with the stages working in `scratch` (e.g. one per worker thread, whatever result
  // slot the frame goes to).
  void run(const DepthFrame& frame, FrameResult& result, FrameScratch& scratch,
           TunnelContext* context = nullptr, Stage from = Stage::Cloud) const;
  // A one-off frame: the scratch is dropped afterwards, so the result holds no buffers.
  FrameResult run(const DepthFrame& frame, TunnelContext* context = nullptr) const {
    FrameResult r;
    FrameScratch scratch;
    run(frame, r, scratch, context);
    return r;
  }

 private:
  // The stage options derived from params_ once, not per frame (parameter lookups allocate).
  void derive_options();

  Parameters params_;
  CloudOptions cloud_;
  NormalOptions normals_;
  GrowOptions grow_;
  TunnelOptions tunnel_;
  Eigen::Vector3d world_up_ = Eigen::Vector3d::UnitZ();
  std::optional<Eigen::Vector3d> camera_up_;
};

}  // namespace tunnelmap
