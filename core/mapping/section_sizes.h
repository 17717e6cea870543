#pragma once
// The girder's cross-section as each frame measures it itself, band by band: the distance
// between two opposite wall patches of one frame, which the frame's pose does not enter. It
// tells where the section changes at a plate, whatever the odometry did there (StructureSlam
// then does not hold the walls' distances across that plate).
#include <map>
#include <utility>
#include <vector>

#include "core/mapping/slam_patches.h"

namespace tunnelmap {

class SectionSizes {
 public:
  // Each pair of opposite wall patches of one band in one frame's `patches`: their distance
  // along their mean outward normal.
  void record(const std::vector<FramePatch>& patches);

  // How the width (`dimension` 0) or the height (1) changes from the bands `before` to the
  // bands `after`; NaN where the views cannot tell. A frame may take a middle plate for the
  // outer surface (alone, one looks like the other), and its size then comes out a plate's
  // thickness short on that wall: a band's views cluster at up to four sizes, a plate's
  // thickness or two apart. Where both sides show more than one cluster, the largest and the
  // smallest clusters must change alike, within `tolerance_m`. Where one side shows one
  // cluster, it may be any of the other side's, and the change is the smallest that agrees
  // with that; where both show one, nothing tells which zones they are.
  double change(int dimension, const std::vector<long>& before, const std::vector<long>& after,
                double tolerance_m) const;

 private:
  // The smallest and the largest of the sizes in `bands` at which two views or more agree
  // (each the median of its views); NaN when none do.
  struct Extremes {
    double smallest, largest;
  };
  Extremes clustered_extremes(int dimension, const std::vector<long>& bands) const;

  std::map<std::pair<int, long>, std::vector<double>> sizes_;  // (0 width / 1 height, band)
};

}  // namespace tunnelmap
