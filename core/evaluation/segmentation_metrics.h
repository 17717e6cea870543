#pragma once
// Plane segmentation quality against per-pixel ground-truth surfaces (simulator surface_id or a
// dataset's gt_surfaces image). A detected plane is correct when at least `overlap` (80 %) of
// its labelled pixels lie on one true planar surface; precision = correct / detected planes.
// A true surface counts when it covers at least `min_surface_pixels` pixels of the frame; it
// is found when a correct plane matched it; recall = found / counted surfaces.
#include <cstdint>
#include <vector>

#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct SegmentationScore {
  long planes = 0, correct_planes = 0;
  long surfaces = 0, found_surfaces = 0;

  double precision() const { return planes ? double(correct_planes) / planes : 0.0; }
  double recall() const { return surfaces ? double(found_surfaces) / surfaces : 0.0; }
  SegmentationScore& operator+=(const SegmentationScore& o);
};

struct SegmentationOptions {
  double overlap = 0.8;
  int min_surface_pixels = 3000;  // ~1 % of VGA: ignores slivers such as plate step faces
  std::uint16_t non_planar_id = 65535;  // rivets: never a correct match
};

// `truth`: width*height ids (0 = nothing). Throws InputError("", ...) when sizes differ.
SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const SegmentationOptions& options = SegmentationOptions());

}  // namespace tunnelmap
