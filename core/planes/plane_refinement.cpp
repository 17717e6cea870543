#include "core/planes/plane_refinement.h"

#include <algorithm>
#include <cmath>

#include "core/planes/plane_growing.h"

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

namespace {

// The final eq. 4 model of one plane in the form of the growing tests.
struct PlaneTest {
  float nx = 0, ny = 0, nz = 0, d = 0;  // unit mean normal n*, d = n*.p*
  // Point-to-plane distance if the pixel passes both eq. 2 tests, else a negative number.
  float distance_if_passes(const float* p, const float* n, float eps, float cos_angle) const {
    const float dist = std::abs(nx * p[0] + ny * p[1] + nz * p[2] - d);
    return dist <= eps && nx * n[0] + ny * n[1] + nz * n[2] >= cos_angle ? dist : -1.0f;
  }
};

}  // namespace

void refine_to_full_resolution(const OrganizedCloud& full, int step, const GrowOptions& options,
                               PlaneSegments& planes) {
  const int w = full.width, h = full.height;
  const int cw = planes.width, ch = planes.height;
  const float eps = static_cast<float>(options.distance_m);
  const float cos_angle = static_cast<float>(std::cos(options.angle_deg * M_PI / 180.0));

  thread_local std::vector<PlaneTest> tests;
  thread_local std::vector<std::int32_t> coarse;
  thread_local std::vector<double> z3;
  thread_local std::vector<int> count, u0, v0, u1, v1, col0, col1;
  const std::size_t k = planes.planes.size() + 1;  // indexed by plane id (1-based)
  tests.assign(k, PlaneTest{});
  z3.assign(k, 0.0), count.assign(k, 0);
  u0.assign(k, w), v0.assign(k, h), u1.assign(k, -1), v1.assign(k, -1);
  for (const PlaneSegment& p : planes.planes) {
    PlaneTest& t = tests[p.id];
    t.nx = static_cast<float>(p.mean_normal.x()), t.ny = static_cast<float>(p.mean_normal.y());
    t.nz = static_cast<float>(p.mean_normal.z());
    t.d = static_cast<float>(p.mean_normal.dot(p.centroid));
  }
  coarse.swap(planes.labels);  // coarse labels in, full-resolution labels out
  planes.labels.assign(static_cast<std::size_t>(w) * h, 0);
  planes.width = w, planes.height = h;

  // The grown sample columns left (at or before) and right (at or after) of each column.
  col0.resize(w), col1.resize(w);
  for (int u = 0; u < w; ++u) col0[u] = u / step, col1[u] = std::min(cw - 1, (u + step - 1) / step);
  const float* pts = full.points.data()->data();
  const float* nrm = full.normals.data()->data();
  for (int v = 0; v < h; ++v) {
    // The grown samples around this row: rows cv0 (at or above) and cv1 (at or below).
    const int cv0 = v / step, cv1 = std::min(ch - 1, (v + step - 1) / step);
    const std::int32_t* r0 = coarse.data() + static_cast<std::size_t>(cv0) * cw;
    const std::int32_t* r1 = coarse.data() + static_cast<std::size_t>(cv1) * cw;
    std::int32_t* out = planes.labels.data() + static_cast<std::size_t>(v) * w;
    for (int u = 0; u < w; ++u) {
      const int cu0 = col0[u], cu1 = col1[u];
      // Candidate planes: the four surrounding samples; most pixels see only one plane. Where
      // planes meet (e.g. zone plates a few mm apart) the closest plane that passes wins.
      const std::int32_t c[4] = {r0[cu0], r0[cu1], r1[cu0], r1[cu1]};
      if ((c[0] | c[1] | c[2] | c[3]) == 0) continue;
      const std::size_t i = static_cast<std::size_t>(v) * w + u;
      const float* p = pts + 3 * i;
      const float* n = nrm + 3 * i;
      if (n[0] != n[0]) continue;  // no normal: never joins a plane
      std::int32_t label = 0;
      float best = eps + 1.0f;
      for (int q = 0; q < 4; ++q) {
        if (c[q] == 0 || (q > 0 && c[q] == c[q - 1]) || c[q] == label) continue;
        const float dist = tests[c[q]].distance_if_passes(p, n, eps, cos_angle);
        if (dist >= 0.0f && dist < best) best = dist, label = c[q];
      }
      if (!label) continue;
      out[u] = label;
      ++count[label];
      z3[label] += static_cast<double>(p[2]) * p[2] * p[2];
      u0[label] = std::min(u0[label], u), u1[label] = std::max(u1[label], u);
      v0[label] = std::min(v0[label], v), v1[label] = std::max(v1[label], v);
    }
  }

  const double fxfy = full.intrinsics.fx * full.intrinsics.fy;
  bool dropped = false;
  for (PlaneSegment& p : planes.planes) {
    p.points = count[p.id];
    p.area_m2 = std::abs(p.offset_m) > 1e-9 ? z3[p.id] / (fxfy * std::abs(p.offset_m)) : 0.0;
    p.bbox_u0 = u0[p.id], p.bbox_v0 = v0[p.id], p.bbox_u1 = u1[p.id], p.bbox_v1 = v1[p.id];
    // The minimum size applies at full resolution too.
    if (p.points < options.min_points || p.area_m2 < options.min_area_m2) dropped = true, count[p.id] = -1;
  }
  if (!dropped) return;
  planes.planes.erase(std::remove_if(planes.planes.begin(), planes.planes.end(),
                                     [&](const PlaneSegment& p) { return count[p.id] < 0; }),
                      planes.planes.end());
  for (std::int32_t& l : planes.labels)
    if (l > 0 && count[l] < 0) l = 0;
}

}  // namespace tunnelmap
