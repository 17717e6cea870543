#include "core/planes/cell_pixel_labels.h"

#include <algorithm>
#include <cmath>
#include <emmintrin.h>

#include "core/util/sse_xyz.h"

namespace tunnelmap {

namespace {

// Writes `id` to the valid pixels of [u0, u1) x [v0, v1), 0 to the others.
void label_valid_pixels(const OrganizedCloud& cloud, int u0, int v0, int u1, int v1, std::int32_t id,
                        std::int32_t* labels) {
  const __m128i id4 = _mm_set1_epi32(id);
  for (int v = v0; v < v1; ++v) {
    const float* p = cloud.points[cloud.index(0, v)].data();
    std::int32_t* l = labels + cloud.index(0, v);
    int u = u0;
    for (; u + 4 <= u1; u += 4) {
      __m128 x, y, z;
      load_xyz4(p + 3 * u, x, y, z);
      const __m128i ok = _mm_castps_si128(_mm_cmpeq_ps(z, z));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(l + u), _mm_and_si128(ok, id4));
    }
    for (; u < u1; ++u) l[u] = p[3 * u + 2] == p[3 * u + 2] ? id : 0;
  }
}

// In a cell that joined plane `own` as a whole, a neighbouring plane that coincides with it
// there (normals within kCoincidentDeg, the cell's centroid within kCoincidentOffset epsilon of
// it) takes none of the pixels: both pass eq. 2's distance test, and which one is nearer is the
// noise's choice. Measured: the bands a curved tunnel is cut into met in salt-and-pepper borders,
// which cost a third of cape's border assignment and longer contours. Returns the candidates
// left in cand[0, n).
constexpr double kCoincidentDeg = 8.0;
constexpr double kCoincidentOffset = 0.5;
struct Coincidence {
  float cos_max, max_offset;
  explicit Coincidence(double eps)
      : cos_max(static_cast<float>(std::cos(kCoincidentDeg * M_PI / 180.0))),
        max_offset(static_cast<float>(kCoincidentOffset * eps)) {}
};
int drop_coincident_planes(const std::vector<Eigen::Vector4f>& planes, std::int32_t own, const Eigen::Vector3d& mean,
                           const Coincidence& bound, std::int32_t* cand, int n) {
  const Eigen::Vector4f& a = planes[own - 1];
  const Eigen::Vector3f m = mean.cast<float>();
  int kept = 0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector4f& b = planes[cand[k] - 1];
    const bool coincident = cand[k] != own && a.head<3>().dot(b.head<3>()) >= bound.cos_max &&
                            std::abs(b.head<3>().dot(m) + b.w()) <= bound.max_offset;
    if (!coincident) cand[kept++] = cand[k];
  }
  return kept;
}

}  // namespace

// A labelled cell passed the eq. 2 tests as a whole: with no other plane among its 4 neighbours
// (coincident ones aside) it keeps all its valid pixels. A plane that touches it only at a corner
// takes none of them: measured on the simulated lab and field frames, recall and precision do not
// drop, and cape's tunnel frame has 1,917 border cells instead of 2,312. A free cell's candidates
// are the planes of its 8 neighbours.
void assign_cell_pixels(const OrganizedCloud& cloud, const CellGrid& grid, double eps,
                        const std::vector<std::int32_t>& cell_labels, const std::vector<Eigen::Vector4f>& planes,
                        std::vector<PixelTally>& tallies, PlaneSegments& out) {
  const int w = cloud.width, c = grid.cell_px;
  out.labels.resize(static_cast<std::size_t>(w) * cloud.height);
  const float epsf = static_cast<float>(eps);
  const Coincidence coincidence(eps);
  for (int cv = 0; cv < grid.rows; ++cv) {
    const int v0 = cv * c, v1 = std::min(cloud.height, v0 + c);
    for (int cu = 0; cu < grid.cols; ++cu) {
      const int u0 = cu * c, u1 = std::min(w, u0 + c);
      const int ci = grid.index(cu, cv);
      const std::int32_t own = cell_labels[ci];
      std::int32_t cand[9];
      int ncand = 0;
      const auto consider = [&](std::int32_t l) {
        if (l > 0 && std::find(cand, cand + ncand, l) == cand + ncand) cand[ncand++] = l;
      };
      const std::int32_t* labels = cell_labels.data();
      if (own > 0) {  // the 4 neighbours, in raster order
        if (cv > 0) consider(labels[ci - grid.cols]);
        if (cu > 0) consider(labels[ci - 1]);
        consider(own);
        if (cu + 1 < grid.cols) consider(labels[ci + 1]);
        if (cv + 1 < grid.rows) consider(labels[ci + grid.cols]);
        if (ncand > 1)
          ncand = drop_coincident_planes(planes, own, grid.cells[ci].mean, coincidence, cand, ncand);
      } else {
        for (int nv = std::max(0, cv - 1); nv <= std::min(grid.rows - 1, cv + 1); ++nv)
          for (int nu = std::max(0, cu - 1); nu <= std::min(grid.cols - 1, cu + 1); ++nu)
            consider(labels[grid.index(nu, nv)]);
      }
      if (ncand == 0) {
        for (int v = v0; v < v1; ++v) std::fill_n(out.labels.data() + cloud.index(u0, v), u1 - u0, 0);
        continue;
      }
      if (own > 0 && ncand == 1) {
        const CellFit& f = grid.cells[ci];
        PixelTally& t = tallies[own - 1];
        t.count += f.count, t.sum_p += f.sum_p, t.sum_z3 += f.sum_z3;
        t.include_box(u0, v0, u1 - 1, v1 - 1);
        if (f.count == (u1 - u0) * (v1 - v0))  // no invalid pixel: no need to look
          for (int v = v0; v < v1; ++v) std::fill_n(out.labels.data() + cloud.index(u0, v), u1 - u0, own);
        else
          label_valid_pixels(cloud, u0, v0, u1, v1, own, out.labels.data());
        continue;
      }
      assign_to_nearest_plane(cloud, u0, v0, u1, v1, planes.data(), cand, ncand, epsf, out.labels.data(),
                              tallies.data());
    }
  }
}

}  // namespace tunnelmap
