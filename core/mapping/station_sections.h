#pragma once
// Splits a station profile into sections of constant cross-section. A station that differs from
// the current section by more than `change_m` in width or height starts a new section only when
// at least `min_run` measured stations in a row agree with it; a shorter run is an outlier.
#include <vector>

namespace tunnelmap {

struct SectionRun {
  int first = 0, last = 0;  // station indices, inclusive
  double width_m = 0.0, height_m = 0.0;  // medians of the accepted measured stations (NaN: none)
  // Where its joint with the section before lies unseen (a plate hid it): the stretch's length
  // in stations, the joint in its middle; -1 where frames saw the step.
  int unseen_joint_stations = -1;
};

struct SectionSplit {
  std::vector<SectionRun> sections;  // in order, covering every station
  std::vector<bool> outlier;         // per station: a measured value rejected as an outlier
};

// `width_m[k]`, `height_m[k]`: measured values per station, NaN where not measured.
SectionSplit split_sections(const std::vector<double>& width_m, const std::vector<double>& height_m,
                            double change_m, int min_run);

}  // namespace tunnelmap
