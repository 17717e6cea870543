#pragma once
// Plane segmentation quality against per-pixel ground-truth surfaces (simulator surface_id or a
// dataset's gt_surfaces image).
//
// A detected plane is correct when at least `overlap` (default 80 %) of its labelled pixels,
// and always a strict majority of them, lie on one true planar surface; precision = correct /
// detected planes. A true surface is found when a correct plane lies on it; recall = found /
// counted surfaces.
//
// Which true surfaces count:
//  - pixel criterion (both overloads): the surface covers >= `min_surface_pixels` pixels of the
//    frame (dropped-out pixels included);
//  - physical criterion (the OrganizedCloud overload only): its visible part (pixels with a
//    valid 3-D point) has >= `min_surface_points` pixels and an area >= `min_surface_area_m2`.
//    The area is the sum of the visible pixels' footprints z^3 / (fx fy |n.p|) on the
//    surface's plane n, fitted by least squares to those pixels' points -- the same footprint
//    PG&C uses for grow.min_area_m2, so "larger than the minimum area" means the same thing.
// SegmentationOptions::by_size() is the plane recall definition of docs/recall.md: physical
// criterion only, majority overlap.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
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
  // Physical criterion, applied by the OrganizedCloud overload (defaults = GrowOptions').
  int min_surface_points = 40;
  double min_surface_area_m2 = 0.004;

  // docs/recall.md: a surface counts when its visible part has >= min_points pixels and >= min_area_m2
  // (no pixel minimum); a plane is correct when > 50 % of its pixels lie on one surface.
  static SegmentationOptions by_size(int min_points, double min_area_m2);
};

// Why a true surface was or was not counted / found (one per true planar surface in view).
struct SurfaceDetail {
  int id = 0;
  long truth_pixels = 0;     // all pixels of the surface, dropped-out ones included
  long pixels = 0;           // visible pixels (valid 3-D point); = truth_pixels without a cloud
  double area_m2 = 0.0;      // visible area (0 without a cloud)
  double mean_depth_m = 0.0; // mean z of the visible pixels (0 without a cloud)
  double incidence_deg = 0.0;  // fitted normal vs. the viewing ray to the centroid (0 without a cloud)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // fitted, facing the camera (zero without a cloud)
  bool counted = false;
  bool found = false;
  int best_plane = 0;            // plane id with the most pixels on this surface (0 = none)
  long best_plane_pixels = 0;    // that plane's pixels on this surface
  double best_plane_share = 0.0; // fraction of that plane's pixels on this surface (the overlap test)
  long labelled_pixels = 0;      // visible pixels of the surface carrying any plane label
};

// `truth`: width*height ids (0 = nothing). Throws InputError("", ...) when sizes differ.
// `details`, when given, receives one SurfaceDetail per true planar surface, sorted by id.
SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const SegmentationOptions& options = SegmentationOptions(),
                                     std::vector<SurfaceDetail>* details = nullptr);

// The same with the physical criterion: `cloud` is the frame's organised cloud (same size).
SegmentationScore score_segmentation(const PlaneSegments& planes,
                                     const std::vector<std::uint16_t>& truth,
                                     const OrganizedCloud& cloud,
                                     const SegmentationOptions& options = SegmentationOptions(),
                                     std::vector<SurfaceDetail>* details = nullptr);

}  // namespace tunnelmap
