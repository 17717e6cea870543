#include "core/planes/plane_refinement.h"

#include <algorithm>
#include <cmath>

#include "core/planes/grazing_growth.h"
#include "core/planes/plane_growing.h"
#include "core/planes/plane_model.h"
#include "core/planes/plane_slots.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

void subsample_cloud(const OrganizedCloud& full, int step, OrganizedCloud& coarse) {
  const int cw = (full.width + step - 1) / step, ch = (full.height + step - 1) / step;
  coarse.width = cw, coarse.height = ch;
  coarse.intrinsics = full.intrinsics;
  coarse.intrinsics.width = cw, coarse.intrinsics.height = ch;
  coarse.intrinsics.fx = full.intrinsics.fx / step, coarse.intrinsics.fy = full.intrinsics.fy / step;
  coarse.intrinsics.cx = full.intrinsics.cx / step, coarse.intrinsics.cy = full.intrinsics.cy / step;
  coarse.points.resize(static_cast<std::size_t>(cw) * ch);
  coarse.normals.resize(coarse.points.size());
  for (int cv = 0; cv < ch; ++cv)
    for (int cu = 0; cu < cw; ++cu) {
      const std::size_t src = full.index(cu * step, cv * step), dst = coarse.index(cu, cv);
      coarse.points[dst] = full.points[src];
      coarse.normals[dst] = full.normals[src];
    }
}

using PlaneTest = RefinementScratch::PlaneTest;

void refine_to_full_resolution(const OrganizedCloud& full, int step, const GrowOptions& options,
                               PlaneSegments& planes, std::vector<std::int32_t>& coarse,
                               std::vector<std::uint8_t>* edge_on, RefinementScratch& scratch,
                               ContourBufferPool& pool) {
  const int w = full.width, h = full.height;
  const int cw = planes.width, ch = planes.height;
  const float eps = static_cast<float>(options.distance_m);
  const float cos_angle = static_cast<float>(std::cos(options.angle_deg * M_PI / 180.0));

  std::vector<PlaneTest>& tests = scratch.tests;
  std::vector<PlaneModel>& models = scratch.models;  // the full-resolution members' eq. 4 sums
  std::vector<int>& u0 = scratch.u0;
  std::vector<int>& v0 = scratch.v0;
  std::vector<int>& u1 = scratch.u1;
  std::vector<int>& v1 = scratch.v1;
  std::vector<int>& col0 = scratch.col0;
  std::vector<int>& col1 = scratch.col1;
  const std::size_t k = planes.planes.size() + 1;  // indexed by plane id (1-based)
  tests.assign(k, PlaneTest{});
  models.assign(k, PlaneModel{});
  u0.assign(k, w), v0.assign(k, h), u1.assign(k, -1), v1.assign(k, -1);
  for (const PlaneSegment& p : planes.planes) {
    PlaneTest& t = tests[p.id];
    t.nx = static_cast<float>(p.mean_normal.x()), t.ny = static_cast<float>(p.mean_normal.y());
    t.nz = static_cast<float>(p.mean_normal.z());
    t.d = static_cast<float>(p.mean_normal.dot(p.centroid));
  }
  // Coarse labels in, full-resolution labels out (copied, not swapped: each buffer keeps its
  // capacity, so no allocation per frame).
  coarse.assign(planes.labels.begin(), planes.labels.end());
  planes.labels.assign(static_cast<std::size_t>(w) * h, 0);
  planes.width = w, planes.height = h;

  // The grown sample columns left (at or before) and right (at or after) of each column.
  col0.resize(w), col1.resize(w);
  for (int u = 0; u < w; ++u) col0[u] = u / step, col1[u] = std::min(cw - 1, (u + step - 1) / step);
  const float* pts = full.points.data()->data();
  const float* nrm = full.normals.data()->data();
  const float focal = static_cast<float>(0.5 * (full.intrinsics.fx + full.intrinsics.fy));
  const float cand = static_cast<float>(options.candidate_distance_m);
  // The edge-on pass's pixel states, classified here while each pixel is in cache.
  const auto state_of = [&](const float* p, const float* n) -> std::uint8_t {
    if (n[0] != n[0]) return kEdgeOnTaken;
    return grid_cannot_connect(Eigen::Vector3f(p[0], p[1], p[2]), Eigen::Vector3f(n[0], n[1], n[2]), step, focal, cand)
               ? kEdgeOnSeed
               : kEdgeOnJoinable;
  };
  if (edge_on) edge_on->resize(static_cast<std::size_t>(w) * h);
  for (int v = 0; v < h; ++v) {
    std::uint8_t* state = edge_on ? edge_on->data() + static_cast<std::size_t>(v) * w : nullptr;
    // The grown samples around this row: rows cv0 (at or above) and cv1 (at or below).
    const int cv0 = v / step, cv1 = std::min(ch - 1, (v + step - 1) / step);
    const std::int32_t* r0 = coarse.data() + static_cast<std::size_t>(cv0) * cw;
    const std::int32_t* r1 = coarse.data() + static_cast<std::size_t>(cv1) * cw;
    std::int32_t* out = planes.labels.data() + static_cast<std::size_t>(v) * w;
    // Consecutive pixels of a row mostly join the same plane: their sums collect in a local
    // model (registers) and reach the plane's model once per run, not once per pixel.
    PlaneModel run;
    std::int32_t run_label = 0;
    int run_u0 = 0, run_u1 = 0;
    const auto flush = [&]() {
      if (!run_label) return;
      models[run_label].merge(run);
      u0[run_label] = std::min(u0[run_label], run_u0), u1[run_label] = std::max(u1[run_label], run_u1);
      v0[run_label] = std::min(v0[run_label], v), v1[run_label] = std::max(v1[run_label], v);
      run = PlaneModel();
    };
    for (int u = 0; u < w; ++u) {
      const int cu0 = col0[u], cu1 = col1[u];
      // Candidate planes: the four surrounding samples; most pixels see only one plane. Where
      // planes meet (e.g. zone plates a few mm apart) the closest plane that passes wins.
      const std::int32_t c[4] = {r0[cu0], r0[cu1], r1[cu0], r1[cu1]};
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const float* p = pts + 3 * i;
      const float* n = nrm + 3 * i;
      std::int32_t label = 0;
      // No normal: never joins a plane.
      if ((c[0] | c[1] | c[2] | c[3]) != 0 && n[0] == n[0]) {
        float best = eps + 1.0f;
        for (int q = 0; q < 4; ++q) {
          if (c[q] == 0 || (q > 0 && c[q] == c[q - 1]) || c[q] == label) continue;
          const float dist = tests[c[q]].distance_if_passes(p, n, eps, cos_angle);
          if (dist >= 0.0f && dist < best) best = dist, label = c[q];
        }
      }
      if (!label) {
        if (state) state[u] = state_of(p, n);
        continue;
      }
      if (state) state[u] = kEdgeOnTaken;
      out[u] = label;
      if (label != run_label) {
        flush();
        run_label = label, run_u0 = u;
      }
      run_u1 = u;
      run.add(Eigen::Vector3f(p[0], p[1], p[2]), Eigen::Vector3f(n[0], n[1], n[2]));
    }
    flush();
  }

  const double fxfy = full.intrinsics.fx * full.intrinsics.fy;
  // Planes below the minimum size at full resolution are dropped and the rest renumbered
  // 1..N in order, so ids stay equal to the label image's values and contiguous.
  std::vector<std::int32_t>& new_id = scratch.new_id;
  new_id.assign(k, 0);
  std::int32_t next = 1;
  bool renumber = false;
  for (PlaneSegment& p : planes.planes) {
    // Every reported quantity from the full-resolution members: four times the points of the
    // grid, so the centroid (and with it the zone offsets) is as precise as every-pixel growing.
    const PlaneModel& m = models[p.id];
    if (m.count() >= 3) {
      fill_segment_statistics(p, m, options, fxfy);
    } else {
      p.points = static_cast<int>(m.count());
      p.area_m2 = 0.0;
    }
    p.bbox_u0 = u0[p.id], p.bbox_v0 = v0[p.id], p.bbox_u1 = u1[p.id], p.bbox_v1 = v1[p.id];
    if (p.points < options.min_points || p.area_m2 < options.min_area_m2) continue;
    new_id[p.id] = next++;
    renumber |= new_id[p.id] != p.id;
  }
  if (!renumber && static_cast<std::size_t>(next - 1) == planes.planes.size()) return;
  // Compact in place, moving kept planes forward (their slots' contour storage travels along).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < planes.planes.size(); ++i) {
    const std::int32_t id = new_id[planes.planes[i].id];
    if (!id) continue;
    if (kept != i) std::swap(planes.planes[kept], planes.planes[i]);
    planes.planes[kept++].id = id;
  }
  shrink_plane_slots(planes.planes, kept, pool);
  if (edge_on) {
    // The pixels of dropped planes are free again: found within each dropped plane's box (a
    // small plane's box is small), before the relabelling below erases them.
    for (std::size_t id = 1; id < k; ++id) {
      if (new_id[id] || u1[id] < 0) continue;
      for (int v = v0[id]; v <= v1[id]; ++v) {
        const std::size_t row = static_cast<std::size_t>(v) * w;
        for (int u = u0[id]; u <= u1[id]; ++u)
          if (planes.labels[row + u] == static_cast<std::int32_t>(id))
            (*edge_on)[row + u] = state_of(pts + 3 * (row + u), nrm + 3 * (row + u));
      }
    }
  }
  // Branch-free: new_id[0] = 0 keeps unlabelled pixels unlabelled.
  const std::int32_t* map = new_id.data();
  for (std::int32_t& l : planes.labels) l = map[l];
  for (std::int32_t& l : coarse) l = map[l];
}

}  // namespace tunnelmap
