#include "core/evaluation/segmentation_metrics.h"

#include <map>
#include <set>

#include "core/util/error.h"

namespace tunnelmap {

SegmentationScore& SegmentationScore::operator+=(const SegmentationScore& o) {
  planes += o.planes;
  correct_planes += o.correct_planes;
  surfaces += o.surfaces;
  found_surfaces += o.found_surfaces;
  return *this;
}

SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const SegmentationOptions& o) {
  if (truth.size() != planes.labels.size())
    throw InputError("", "ground-truth surface image has " + std::to_string(truth.size()) +
                             " pixels but the plane labels " + std::to_string(planes.labels.size()));
  // Per plane: histogram of the true ids under its pixels.
  std::map<int, std::map<int, long>> overlap;
  std::map<int, long> surface_pixels;
  for (size_t i = 0; i < truth.size(); ++i) {
    const int t = truth[i];
    if (t != 0 && t != o.non_planar_id) ++surface_pixels[t];
    if (planes.labels[i] > 0) ++overlap[planes.labels[i]][t];
  }
  SegmentationScore s;
  std::set<int> found;
  for (const PlaneSegment& p : planes.planes) {
    ++s.planes;
    const auto it = overlap.find(p.id);
    if (it == overlap.end()) continue;
    long total = 0, best = 0;
    int best_id = 0;
    for (const auto& [t, n] : it->second) {
      total += n;
      if (t != 0 && t != o.non_planar_id && n > best) {
        best = n;
        best_id = t;
      }
    }
    if (total > 0 && best >= o.overlap * total) {
      ++s.correct_planes;
      found.insert(best_id);
    }
  }
  for (const auto& [t, n] : surface_pixels) {
    if (n < o.min_surface_pixels) continue;
    ++s.surfaces;
    s.found_surfaces += found.count(t) ? 1 : 0;
  }
  return s;
}

}  // namespace tunnelmap
