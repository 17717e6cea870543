#pragma once
// Coarse-to-fine PG&C (the default fast path): the planes are grown on every `step`-th pixel of
// every `step`-th row, then each full-resolution pixel is assigned to the plane of a nearby
// grown sample if it passes the same eq. 2 tests (point-to-plane distance epsilon and normal
// angle lambda) against that plane's final model.
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/frame/organized_cloud.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_segment.h"
#include "core/planes/plane_slots.h"

namespace tunnelmap {

struct GrowOptions;

// Samples pixel (step*cu, step*cv) of `full` into `coarse` (intrinsics scaled accordingly).
void subsample_cloud(const OrganizedCloud& full, int step, OrganizedCloud& coarse);

// The buffers of refine_to_full_resolution, indexed by plane id, kept by the caller (PlaneScratch).
struct RefinementScratch {
  // The final eq. 4 model of one plane in the form of the growing tests.
  struct PlaneTest {
    float nx = 0, ny = 0, nz = 0, d = 0;  // unit mean normal n*, d = n*.p*
    // Point-to-plane distance if the pixel passes both eq. 2 tests, else a negative number.
    float distance_if_passes(const float* p, const float* n, float eps, float cos_angle) const {
      const float dist = std::abs(nx * p[0] + ny * p[1] + nz * p[2] - d);
      return dist <= eps && nx * n[0] + ny * n[1] + nz * n[2] >= cos_angle ? dist : -1.0f;
    }
  };
  std::vector<PlaneTest> tests;
  std::vector<PlaneModel> models;    // the full-resolution members' eq. 4 sums
  std::vector<int> u0, v0, u1, v1;   // the full-resolution members' bounding boxes
  std::vector<int> col0, col1;       // per column: the grown sample columns left and right
  std::vector<std::int32_t> new_id;  // after dropping planes below the minimum size
};

// `planes` holds the planes grown on the `step` grid with their coarse label image; on return
// its labels are full resolution and every reported quantity (points, area, centroid, normals,
// offset, RMS, bounding box) is that of the full-resolution members. Planes below the minimum
// size at full resolution are dropped and the rest renumbered 1..N; `coarse` receives the grid's
// label image with the same ids (for tracing contours at the grid's resolution). With
// `edge_on`, every pixel's state for grow_edge_on_surfaces (kEdgeOn*) is classified on the way.
// Allocation-free in the steady state: `scratch` keeps its buffers, `pool` takes the contour
// buffers of dropped planes.
void refine_to_full_resolution(const OrganizedCloud& full, int step, const GrowOptions& options,
                               PlaneSegments& planes, std::vector<std::int32_t>& coarse,
                               std::vector<std::uint8_t>* edge_on, RefinementScratch& scratch,
                               ContourBufferPool& pool);

}  // namespace tunnelmap
