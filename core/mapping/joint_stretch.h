#pragma once
// Where between two neighbouring sections their joint may lie: the stations after the last
// that measured the first section's size and before the first that measured the second's.
// Where no station measured the stepping dimension whole, a wall that carries the step alone
// (a roof that rises) still tells a station's side.
#include <array>
#include <vector>

#include "core/mapping/station_sections.h"

namespace tunnelmap {

// The joint lies after station `last_a` and at or before station `first_b` (profile indices).
struct JointStretch {
  int last_a = 0, first_b = 0;
  int unmeasured() const { return first_b - last_a - 1; }
  int middle() const { return (last_a + first_b + 1) / 2; }
};

// The dimension in which section `b` steps from `a`: 0 width, 1 height (the larger step).
int stepping_dimension(const SectionRun& a, const SectionRun& b);

// From the stations' sizes (`width_m`, `height_m`: a frame's own, else pooled; NaN unmeasured).
JointStretch stretch_between(const SectionRun& a, const SectionRun& b, const std::vector<double>& width_m,
                             const std::vector<double>& height_m);

// `s` narrowed by the stations inside it where a wall that carries the step was seen
// (`wall_m`: per station left, right, bottom, top; NaN unseen).
JointStretch narrowed_by_walls(const SectionRun& a, const SectionRun& b, JointStretch s,
                               const std::vector<std::array<double, 4>>& wall_m);

}  // namespace tunnelmap
