#include "core/planes/plane_growing.h"

#include <algorithm>
#include <cmath>

#include "core/planes/grazing_growth.h"
#include "core/planes/plane_contour.h"
#include "core/planes/residual_growth.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_refinement.h"
#include "core/planes/plane_scratch.h"
#include "core/planes/plane_slots.h"
#include "core/planes/region_grower.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

namespace {

// PG&C growing over every pixel of `cloud`: planes, labels and bounding boxes, no contours.
void grow_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out,
                 RegionGrower& grower, ContourBufferPool& pool) {
  out.width = cloud.width;
  out.height = cloud.height;
  std::size_t kept = 0;  // out.planes' slots are reused frame after frame (no reallocation)
  const std::size_t n = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (cloud.normals.size() != n || cloud.points.size() != n || n == 0) {
    out.planes.clear();
    out.labels.assign(n, 0);
    return;
  }
  grower.reset(cloud, options);
  const double fxfy = cloud.intrinsics.fx * cloud.intrinsics.fy;
  std::int32_t next_id = 1;
  for (int v = 0; v < cloud.height; ++v) {
    for (int u = 0; u < cloud.width; ++u) {
      if (!grower.seedable(u, v)) continue;
      PlaneModel model;
      if (!grower.seed(u, v, model)) continue;
      grower.grow(u, v, next_id, model);  // `model` already holds the seed block
      if (model.count() < options.min_points) {  // too small: no statistics needed
        grower.release();
        continue;
      }
      if (kept == out.planes.size()) add_plane_slot(out.planes, pool);
      PlaneSegment& plane = out.planes[kept];
      plane.id = next_id;
      fill_segment_statistics(plane, model, options, fxfy);
      if (plane.area_m2 < options.min_area_m2) {
        grower.release();  // the slot is reused by the next region
        continue;
      }
      plane.bbox_u0 = grower.bbox_u0, plane.bbox_v0 = grower.bbox_v0;
      plane.bbox_u1 = grower.bbox_u1, plane.bbox_v1 = grower.bbox_v1;
      ++kept;
      ++next_id;
    }
  }
  shrink_plane_slots(out.planes, kept, pool);
  grower.export_labels(out.labels);
}

}  // namespace

void extract_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out,
                    PlaneScratch& scratch) {
  reset_timings(out.timings_ms);
  StageTimer timer(out.timings_ms, "planes");
  if (options.cell_px > 0) {
    extract_planes_by_cells(cloud, options, out, scratch.cells, scratch.contour_pool);
    const std::size_t cell_planes = out.planes.size();
    if (options.edge_on_pass) {
      StageTimer edge_timer(out.timings_ms, "edge_on");
      grow_residual_slivers(cloud, options, scratch.cells.grid, scratch.cells.cell_labels, out, scratch.residual,
                            scratch.contour_pool);
    }
    if (options.compute_contours) {
      // Traced on every (cell / 2)-th pixel and row: half a cell is the resolution the cells
      // already hold the outline to in their interior. At 8 px cells this is 3x cheaper than
      // tracing every second pixel, with the same Table 1 (docs/performance.md).
      StageTimer contour_timer(out.timings_ms, "contours");
      const int kStep = std::max(2, options.cell_px / 2);
      Intrinsics half = cloud.intrinsics;
      const int hw = (cloud.width + kStep - 1) / kStep, hh = (cloud.height + kStep - 1) / kStep;
      half.width = hw, half.height = hh;
      half.fx /= kStep, half.fy /= kStep, half.cx /= kStep, half.cy /= kStep;
      std::vector<std::int32_t>& half_labels = scratch.coarse_labels;
      half_labels.resize(static_cast<std::size_t>(hw) * hh);
      for (int v = 0; v < hh; ++v)
        for (int u = 0; u < hw; ++u)
          half_labels[static_cast<std::size_t>(v) * hw + u] = out.labels[cloud.index(u * kStep, v * kStep)];
      for (std::size_t i = 0; i < out.planes.size(); ++i) {
        PlaneSegment& plane = out.planes[i];
        if (i >= cell_planes) {  // a sliver of the residual pass: a few pixels wide
          compute_contour(out.labels, cloud.width, cloud.intrinsics, plane, scratch.contour);
          continue;
        }
        const int u0 = plane.bbox_u0, v0 = plane.bbox_v0, u1 = plane.bbox_u1, v1 = plane.bbox_v1;
        plane.bbox_u0 = u0 / kStep, plane.bbox_v0 = v0 / kStep;
        plane.bbox_u1 = std::min(hw - 1, (u1 + kStep - 1) / kStep);
        plane.bbox_v1 = std::min(hh - 1, (v1 + kStep - 1) / kStep);
        compute_contour(half_labels, hw, half, plane, scratch.contour);
        plane.bbox_u0 = u0, plane.bbox_v0 = v0, plane.bbox_u1 = u1, plane.bbox_v1 = v1;
      }
    }
    return;
  }
  const int step = std::max(1, options.grid_step);
  if (step == 1) {
    {
      StageTimer grow_timer(out.timings_ms, "grow");
      grow_planes(cloud, options, out, scratch.grower, scratch.contour_pool);
    }
    if (options.compute_contours) {
      StageTimer contour_timer(out.timings_ms, "contours");
      for (PlaneSegment& plane : out.planes)
        compute_contour(out.labels, cloud.width, cloud.intrinsics, plane, scratch.contour);
    }
    return;
  }
  OrganizedCloud& coarse = scratch.coarse;
  std::vector<std::int32_t>& coarse_labels = scratch.coarse_labels;
  std::vector<std::uint8_t>& edge_on_states = scratch.edge_on_states;
  {
    StageTimer grow_timer(out.timings_ms, "grow");
    subsample_cloud(cloud, step, coarse);
    GrowOptions coarse_options = options;
    // Each sample stands for step^2 pixels; the full-resolution minimum is enforced after refinement.
    coarse_options.min_points = std::max(4, options.min_points / (step * step));
    grow_planes(coarse, coarse_options, out, scratch.grower, scratch.contour_pool);
  }
  {
    StageTimer refine_timer(out.timings_ms, "refine");
    refine_to_full_resolution(cloud, step, options, out, coarse_labels,
                              options.edge_on_pass ? &edge_on_states : nullptr, scratch.refinement,
                              scratch.contour_pool);
  }
  const std::size_t grid_planes = out.planes.size();
  if (options.edge_on_pass) {
    StageTimer edge_timer(out.timings_ms, "edge_on");
    grow_edge_on_surfaces(cloud, options, out, edge_on_states, scratch.edge_on_grower, scratch.contour_pool);
  }
  if (options.compute_contours) {
    // The outline at the growing grid's resolution (step times fewer pixels to trace); the
    // coarse intrinsics map a sample's pixel to the same ray as its full-resolution pixel.
    StageTimer contour_timer(out.timings_ms, "contours");
    for (std::size_t i = 0; i < out.planes.size(); ++i) {
      PlaneSegment& plane = out.planes[i];
      if (i >= grid_planes) {  // found by the edge-on pass: it has no grid samples
        compute_contour(out.labels, cloud.width, cloud.intrinsics, plane, scratch.contour);
        continue;
      }
      // Trace with the bounding box in grid coordinates, then restore the full-resolution box.
      const int u0 = plane.bbox_u0, v0 = plane.bbox_v0, u1 = plane.bbox_u1, v1 = plane.bbox_v1;
      plane.bbox_u0 = u0 / step, plane.bbox_v0 = v0 / step;
      plane.bbox_u1 = std::min(coarse.width - 1, (u1 + step - 1) / step);
      plane.bbox_v1 = std::min(coarse.height - 1, (v1 + step - 1) / step);
      compute_contour(coarse_labels, coarse.width, coarse.intrinsics, plane, scratch.contour);
      plane.bbox_u0 = u0, plane.bbox_v0 = v0, plane.bbox_u1 = u1, plane.bbox_v1 = v1;
    }
  }
}

void extract_planes(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out) {
  PlaneScratch scratch;
  extract_planes(cloud, options, out, scratch);
}

PlaneSegments extract_planes(const OrganizedCloud& cloud, const GrowOptions& options) {
  PlaneSegments out;
  extract_planes(cloud, options, out);
  return out;
}

}  // namespace tunnelmap
