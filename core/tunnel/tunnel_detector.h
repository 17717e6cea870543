#pragma once
// Stage 4: robust tunnel detection (paper section 2.2): classify planes into wall classes,
// reject outliers by histogram, cluster zone positions, fit the rectangular template.
#include <Eigen/Core>
#include <vector>

#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"
#include "core/tunnel/tunnel_options.h"  // TunnelOptions

namespace tunnelmap {

// Context of previous scans in a sequence without poses: the widths and heights earlier frames
// measured. A new frame's measured dimensions must agree with it within context_tolerance_m.
// (Posed sequences use the station map along the tunnel instead: core/mapping.)
class TunnelContext {
 public:
  // The context is the last kWindow measurements of each dimension: bounded memory and time per
  // frame on hours-long streams (the robot moves on; old scans say least about the tunnel here).
  static constexpr std::size_t kWindow = 1000;

  void accept(const TunnelMap& map);  // takes the dimensions the map measured
  bool empty() const { return width_.values.empty() && height_.values.empty(); }
  bool has_width() const { return !width_.values.empty(); }
  bool has_height() const { return !height_.values.empty(); }
  double width_m() const { return width_.median; }    // median of accepted widths (0 when none)
  double height_m() const { return height_.median; }  // median of accepted heights
  void clear() { width_ = Ring(), height_ = Ring(); }

 private:
  struct Ring {
    std::vector<double> values;  // a ring buffer once kWindow values were accepted
    std::size_t next = 0;        // slot the next value replaces when full
    double median = 0.0;         // of `values`, kept up to date by push (0 when empty)
    std::vector<double> work;    // push's copy for the median: reused, no allocation per frame
    void push(double v);
  };
  Ring width_, height_;
};

// `up_camera`: unit vector towards the roof, in the camera frame. Everything in the returned map
// is in the camera frame. `context` may be null (single frame).
TunnelMap detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                        const TunnelOptions& options, const TunnelContext* context);
// The same, written into `map`: every field is reset to what the returned map would hold, but
// the vectors and strings keep their buffers; the stage's own buffers are `scratch`'s
// (core/tunnel/tunnel_scratch.h, one per concurrent caller). Detecting frame after frame into
// one map with one scratch allocates nothing in the steady state (checked by tests/allocation).
struct TunnelScratch;
void detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                   const TunnelOptions& options, const TunnelContext* context, TunnelMap& map,
                   TunnelScratch& scratch);
// The same with scratch of its own: allocates it on every call.
void detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                   const TunnelOptions& options, const TunnelContext* context, TunnelMap& map);

// The context check of step 5 alone, for a map detected without a context: a detected map whose
// width or height differs from the context's by more than context_tolerance_m becomes
// "inconsistent_with_context"; anything else is left unchanged. detect_tunnel(..., context)
// equals detect_tunnel(..., nullptr) followed by this, which lets a sequence detect frames in
// parallel and apply the order-dependent context in frame order (core/pipeline/sequence_runner.h).
// map.reason for a detected map from its sources: "width 0.820 m, height 1.300 m" when both
// were measured, else what was not, e.g. "height from context" or "height unknown".
void describe_tunnel_map(TunnelMap& map);

void apply_tunnel_context(TunnelMap& map, const TunnelOptions& options, const TunnelContext& context);

}  // namespace tunnelmap
