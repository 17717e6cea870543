#pragma once
// Stage 4: robust tunnel detection (paper section 2.2): classify planes into wall classes,
// reject outliers by histogram, cluster zone positions, fit the rectangular template.
#include <Eigen/Core>
#include <vector>

#include "core/planes/plane_segment.h"
#include "core/tunnel/tunnel_map.h"

namespace tunnelmap {

struct TunnelOptions {
  double class_angle_deg = 35.0;
  double outlier_bin_deg = 1.0;
  double outlier_max_deg = 8.0;
  double zone_cluster_m = 0.010;
  int min_cluster_points = 300;
  // Zone support / gap scaling with the wall's distance (zone_support.h); 0 = off.
  double zone_support_ref_m = 0.0;
  double zone_gap_ref_m = 0.0;
  double context_tolerance_m = 0.040;
  double max_pair_angle_deg = 10.0;
  double width_min_m = 0.3, width_max_m = 3.0;
  double height_min_m = 0.3, height_max_m = 3.0;
  double forbidden_band_m = 0.15;
  // Symmetric zone prior (zone_clustering.h): a wall seen only by its middle plate borrows the
  // opposite wall's edge-to-middle step, up to this size (0 = off).
  double max_symmetric_step_m = 0.03;
  // Design prior (0 = none): infers a wall out of view from the opposite wall, or gives the
  // dimension itself when neither wall of the pair was measured.
  double design_width_m = 0.0, design_height_m = 0.0;
};

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
  double width_m() const;   // median of accepted widths (0 when none)
  double height_m() const;  // median of accepted heights
  void clear() { width_ = Ring(), height_ = Ring(); }

 private:
  struct Ring {
    std::vector<double> values;  // a ring buffer once kWindow values were accepted
    std::size_t next = 0;        // slot the next value replaces when full
    void push(double v);
  };
  Ring width_, height_;
};

// `up_camera`: unit vector towards the roof, in the camera frame. Everything in the returned map
// is in the camera frame. `context` may be null (single frame).
TunnelMap detect_tunnel(const PlaneSegments& planes, const Eigen::Vector3d& up_camera,
                        const TunnelOptions& options, const TunnelContext* context);
// The same, written into `map`: every field is reset to what the returned map would hold, but
// the vectors and strings keep their buffers, so detecting frame after frame into one map
// allocates nothing in the steady state (checked by tests/allocation).
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
