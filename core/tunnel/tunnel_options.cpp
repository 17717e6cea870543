#include "core/tunnel/tunnel_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const TunnelOptions& a, const TunnelOptions& b) {
  return a.class_angle_deg == b.class_angle_deg && a.outlier_bin_deg == b.outlier_bin_deg &&
         a.outlier_max_deg == b.outlier_max_deg && a.zone_cluster_m == b.zone_cluster_m &&
         a.min_cluster_points == b.min_cluster_points && a.zone_support_ref_m == b.zone_support_ref_m &&
         a.zone_gap_ref_m == b.zone_gap_ref_m && a.context_tolerance_m == b.context_tolerance_m &&
         a.max_pair_angle_deg == b.max_pair_angle_deg && a.width_min_m == b.width_min_m &&
         a.width_max_m == b.width_max_m && a.height_min_m == b.height_min_m &&
         a.height_max_m == b.height_max_m && a.forbidden_band_m == b.forbidden_band_m &&
         a.max_symmetric_step_m == b.max_symmetric_step_m && a.design_width_m == b.design_width_m &&
         a.design_height_m == b.design_height_m;
}

TunnelOptions tunnel_options(const Parameters& p) {
  using namespace tunnel_keys;
  TunnelOptions o;
  o.class_angle_deg = p.get(class_angle_deg);
  o.outlier_bin_deg = p.get(outlier_bin_deg);
  o.outlier_max_deg = p.get(outlier_max_deg);
  o.zone_cluster_m = mm_to_m(p.get(zone_cluster_mm));
  o.min_cluster_points = p.get(min_cluster_points);
  o.zone_support_ref_m = p.get(zone_support_ref_m);
  o.zone_gap_ref_m = p.get(zone_gap_ref_m);
  o.context_tolerance_m = mm_to_m(p.get(context_tolerance_mm));
  o.max_pair_angle_deg = p.get(max_pair_angle_deg);
  o.width_min_m = p.get(width_min_m);
  o.width_max_m = p.get(width_max_m);
  o.height_min_m = p.get(height_min_m);
  o.height_max_m = p.get(height_max_m);
  o.forbidden_band_m = p.get(forbidden_band_m);
  o.max_symmetric_step_m = mm_to_m(p.get(symmetric_step_max_mm));
  o.design_width_m = p.get(design_width_m);
  o.design_height_m = p.get(design_height_m);
  return o;
}

ParameterGroup tunnel_parameter_group() {
  using namespace tunnel_keys;
  return {{class_angle_deg.spec(), outlier_bin_deg.spec(), outlier_max_deg.spec(), zone_cluster_mm.spec(),
           min_cluster_points.spec(), zone_support_ref_m.spec(), zone_gap_ref_m.spec(),
           context_tolerance_mm.spec(), max_pair_angle_deg.spec(), symmetric_step_max_mm.spec(),
           width_min_m.spec(), width_max_m.spec(), height_min_m.spec(), height_max_m.spec(),
           forbidden_band_m.spec(), design_width_m.spec(), design_height_m.spec()},
          {less_than(width_min_m, width_max_m), less_than(height_min_m, height_max_m)}};
}

}  // namespace tunnelmap
