#include "core/planes/grow_options.h"

#include "core/params/parameters.h"

namespace tunnelmap {

bool operator==(const GrowOptions& a, const GrowOptions& b) {
  return a.angle_deg == b.angle_deg && a.distance_m == b.distance_m &&
         a.candidate_distance_m == b.candidate_distance_m && a.neighbourhood_n == b.neighbourhood_n &&
         a.min_points == b.min_points && a.min_area_m2 == b.min_area_m2 &&
         a.refit_normal == b.refit_normal && a.grid_step == b.grid_step &&
         a.edge_on_pass == b.edge_on_pass && a.cell_px == b.cell_px && a.compute_contours == b.compute_contours;
}

GrowOptions grow_options(const Parameters& p) {
  using namespace grow_keys;
  GrowOptions o;
  o.angle_deg = p.get(angle_deg);
  o.distance_m = mm_to_m(p.get(distance_mm));
  o.candidate_distance_m = mm_to_m(p.get(candidate_distance_mm));
  o.neighbourhood_n = p.get(neighbourhood_n);
  o.min_points = p.get(min_points);
  o.min_area_m2 = p.get(min_area_m2);
  o.refit_normal = p.get(refit_normal);
  o.grid_step = p.get(grid_step);
  o.edge_on_pass = p.get(edge_on_pass);
  o.cell_px = p.get(cell_px);
  return o;
}

ParameterGroup grow_parameter_group() {
  using namespace grow_keys;
  return {{angle_deg.spec(), distance_mm.spec(), candidate_distance_mm.spec(), neighbourhood_n.spec(),
           min_points.spec(), min_area_m2.spec(), refit_normal.spec(), grid_step.spec(),
           edge_on_pass.spec(), cell_px.spec()},
          {odd(neighbourhood_n)}};
}

}  // namespace tunnelmap
