#pragma once
// Coarse-to-fine PG&C (the default fast path): the planes are grown on every `step`-th pixel of
// every `step`-th row, then each full-resolution pixel is assigned to the plane of a nearby
// grown sample if it passes the same eq. 2 tests (point-to-plane distance epsilon and normal
// angle lambda) against that plane's final model.
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap {

struct GrowOptions;

// Samples pixel (step*cu, step*cv) of `full` into `coarse` (intrinsics scaled accordingly).
void subsample_cloud(const OrganizedCloud& full, int step, OrganizedCloud& coarse);

// `planes` holds the planes grown on the `step` grid with their coarse label image; on return
// its labels are full resolution and every reported quantity (points, area, centroid, normals,
// offset, RMS, bounding box) is that of the full-resolution members. Planes below the minimum
// size at full resolution are dropped and the rest renumbered 1..N; `coarse` receives the grid's
// label image with the same ids (for tracing contours at the grid's resolution). With
// `edge_on`, every pixel's state for grow_edge_on_surfaces (kEdgeOn*) is classified on the way.
void refine_to_full_resolution(const OrganizedCloud& full, int step, const GrowOptions& options,
                               PlaneSegments& planes, std::vector<std::int32_t>& coarse,
                               std::vector<std::uint8_t>* edge_on = nullptr);

}  // namespace tunnelmap
