#include "core/baselines/baseline_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const RansacLseOptions& a, const RansacLseOptions& b) {
  return a.iterations == b.iterations && a.sample_step == b.sample_step && a.distance_m == b.distance_m &&
         a.max_planes == b.max_planes && a.min_plane_points == b.min_plane_points &&
         a.max_trials == b.max_trials && a.confidence == b.confidence && a.seed == b.seed;
}

bool operator==(const QhullOptions& a, const QhullOptions& b) {
  return a.sample_step == b.sample_step && a.min_points == b.min_points &&
         a.yaw_range_deg == b.yaw_range_deg && a.tilt_range_deg == b.tilt_range_deg;
}

bool operator==(const BaselineOptions& a, const BaselineOptions& b) {
  return a.ransac == b.ransac && a.qhull == b.qhull;
}

BaselineOptions baseline_options(const Parameters& p) {
  using namespace baseline_keys;
  BaselineOptions o;
  o.ransac.iterations = p.get(ransac_iterations);
  o.ransac.sample_step = p.get(ransac_sample_step);
  o.ransac.distance_m = mm_to_m(p.get(ransac_distance_mm));
  o.ransac.max_planes = p.get(ransac_max_planes);
  o.ransac.min_plane_points = p.get(ransac_min_plane_points);
  o.ransac.max_trials = p.get(ransac_max_trials);
  o.ransac.confidence = p.get(ransac_confidence);
  o.qhull.sample_step = p.get(qhull_sample_step);
  o.qhull.min_points = p.get(qhull_min_points);
  o.qhull.yaw_range_deg = p.get(qhull_yaw_range_deg);
  o.qhull.tilt_range_deg = p.get(qhull_tilt_range_deg);
  return o;
}

ParameterGroup baseline_parameter_group() {
  using namespace baseline_keys;
  return {{ransac_iterations.spec(), ransac_sample_step.spec(), ransac_distance_mm.spec(),
           ransac_max_planes.spec(), ransac_min_plane_points.spec(), ransac_max_trials.spec(),
           ransac_confidence.spec(), qhull_sample_step.spec(), qhull_min_points.spec(),
           qhull_yaw_range_deg.spec(), qhull_tilt_range_deg.spec()},
          {}};
}

}  // namespace tunnelmap
