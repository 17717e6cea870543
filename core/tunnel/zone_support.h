#pragma once
// Zone support and zone gap as a wall gets farther from the camera (step 4 of tunnel detection,
// docs/tunnel-detection.md "Zone support scaling"). A patch of fixed size covers ~1/d^2 pixels
// and structured-light depth noise grows ~d^2, so one point count and one gap cannot suit both
// a 1 m box girder seen from 0.4 m and corridor walls 2-3 m away.

namespace tunnelmap {

// Fewest points a scaled support ever asks for: grow.min_points' default, the smallest plane.
constexpr int kMinScaledZoneSupport = 40;

struct ZoneScaling {
  int min_points = 300;        // tunnel.min_cluster_points: the support at the reference distance
  double support_ref_m = 0.0;  // tunnel.zone_support_ref_m; 0 = min_points at every distance
  double gap_m = 0.010;        // tunnel.zone_cluster_mm: the gap at the reference distance
  double gap_ref_m = 0.0;      // tunnel.zone_gap_ref_m; 0 = gap_m at every distance

  // Points a zone cluster `distance_m` from the camera (its plane offset) needs to bound the
  // tunnel, and a plane needs to link two zone positions: min_points * (ref / d)^2, at least
  // kMinScaledZoneSupport and never above min_points (nearer walls keep the configured support).
  int support_at(double distance_m) const;
  // Gap that starts a new zone at `distance_m`: gap_m * (d / ref)^2, never below gap_m.
  double gap_at(double distance_m) const;
};

// Throws ParameterError (one line) when a reference distance is negative or not finite, or the
// base gap is not positive.
void check_zone_scaling(const ZoneScaling& scaling);

}  // namespace tunnelmap
