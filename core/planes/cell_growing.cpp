#include "core/planes/cell_growing.h"

#include <algorithm>
#include <cmath>

#include "core/planes/cell_pixel_labels.h"
#include "core/planes/disparity_fit.h"
#include "core/planes/segment_statistics.h"

namespace tunnelmap {

namespace {

constexpr int kSeedBuckets = 32;
constexpr double kAngleErrors = 2.0;
constexpr double kContinuitySigmas = 3.0;
constexpr double kContinuityFloor = 0.4;  // of epsilon: 6 mm at the paper's 15 mm
constexpr double kCorrelatedNoise = 1.5;
constexpr std::size_t kRefitFraction = 16;
// Noisy cells (planar by the noise bound only, cell_fits.h): the bound is this many times the
// frame's noise sigma at the cell's range; a region of noisy cells alone needs this many cells
// to stand for a surface, and takes its plane from the block normals for its first cells.
constexpr double kNoiseMultiple = 2.5;
constexpr std::size_t kMinNoisyRegionCells = 4;
constexpr std::size_t kNoisySeedCells = 9;

// cos x for x in [0, pi/2], to 1e-8: the Taylor series to x^12 (libm's cos was 2 % of a frame,
// called for every planar cell).
double cos_to_right_angle(double x) {
  const double x2 = x * x;
  return 1.0 + x2 * (-1.0 / 2 + x2 * (1.0 / 24 + x2 * (-1.0 / 720 + x2 * (1.0 / 40320 +
         x2 * (-1.0 / 3628800 + x2 * (1.0 / 479001600))))));
}

// Planar cells ordered by their fit, flattest first (bucketed, raster order within a bucket):
// regions start where the plane is best defined.
void order_seeds(const CellGrid& grid, double max_mse, CellGrowingScratch& s) {
  s.bucket_start.assign(kSeedBuckets + 1, 0);
  const double scale = kSeedBuckets / std::max(max_mse, 1e-30);
  const auto bucket = [&](const CellFit& c) { return std::min(kSeedBuckets - 1, static_cast<int>(c.mse * scale)); };
  for (const CellFit& c : grid.cells)
    if (c.planar) ++s.bucket_start[bucket(c) + 1];
  for (int b = 0; b < kSeedBuckets; ++b) s.bucket_start[b + 1] += s.bucket_start[b];
  s.seeds.resize(s.bucket_start[kSeedBuckets]);
  for (std::size_t i = 0; i < grid.cells.size(); ++i)
    if (grid.cells[i].planar) s.seeds[s.bucket_start[bucket(grid.cells[i])]++] = static_cast<std::int32_t>(i);
}

// The eq. 4 model for the eq. 2 tests: the unit mean normal n* (the angle test) and the plane
// through the mean point p* (the distance test). That plane's normal is the least-squares one
// of the region's points: over a wall metres long, the mean of noisy cell normals tilts the
// plane by enough to stop the growth part of the way along (measured: walls split in bands).
// The mean normal and the plane's offset follow every join; the least-squares direction is
// refitted whenever the region has grown by a sixteenth since the last fit (it barely turns
// between: a join changes a large region's moments by little), which saves most eigen-solves.
struct GrowthPlane {
  Eigen::Vector3d mean_normal;
  Eigen::Vector3d n;
  double d;
  std::size_t fitted_cells = 0;
  // A noisy seed's own least-squares plane is noise: the plane follows the mean of the block
  // normals until the region spans a block.
  bool noisy_seed = false;

  void refit(const PlaneModel& m) {
    const Eigen::Matrix3d c = m.covariance();
    const double cov[6] = {c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)};
    if (!smallest_eigenvector(cov, n)) n = m.sum_normal().normalized();
  }
  void update(const PlaneModel& m, std::size_t cells) {
    mean_normal = m.sum_normal().normalized();
    if (noisy_seed && cells < kNoisySeedCells) {
      n = mean_normal;
    } else if (cells >= fitted_cells + std::max<std::size_t>(1, fitted_cells / kRefitFraction)) {
      refit(m);
      fitted_cells = cells;
    }
    if (n.dot(mean_normal) < 0) n = -n;
    d = -n.dot(m.mean_point());
  }
};

// Breadth-first over 4-neighbour cells from `seed`; returns with the region's cells in s.queue.
// The surface runs on without a step from region cell `a` to its neighbour `b`: along the
// region's normal `n`, b's centroid lies within 3 standard errors of the two means of a's, or
// within 0.4 epsilon. A zone plate's 8 mm step between two flat cells passes the eq. 2
// distance test (epsilon 15 mm) but not this one; per pixel, the step's own face stops the
// growth through its normals, and a step along a cell border has no such face.
bool continuous(const CellFit& a, const CellFit& b, const Eigen::Vector3d& n, double eps) {
  const double off = std::abs(n.dot(b.mean - a.mean));
  if (off <= kContinuityFloor * eps) return true;  // most joins: no square roots
  // Depth noise is correlated within a cell (disparity quantisation terraces), so the means
  // scatter more than sigma / sqrt(n): 1.5 times the cells' own RMS is allowed too.
  const double off2 = off * off;
  return off2 <= kContinuitySigmas * kContinuitySigmas * (a.mse / a.count + b.mse / b.count) ||
         off2 <= kCorrelatedNoise * kCorrelatedNoise * 0.5 * (a.mse + b.mse);
}

// The eq. 2 tests for neighbour cell `f` of a region with plane `plane`: its block normal
// (cell_fits.h) within lambda (widened by its standard error, `cos_angle`) of the mean normal;
// for a quiet cell its points' RMS to the model plane (exact, from the moments) within epsilon,
// and its centroid within its planarity bound of that plane (epsilon/2, or the noise bound at
// range) or 1.5 times its own RMS: the cells a plate step crosses hold both sides, each with its
// centroid half a step from either, and passed the neighbour-to-neighbour continuity test half a
// step at a time (field preset: 6 mm steps under epsilon 8 mm, widths 2.0 mm off on average
// instead of 1.5);
// for a noisy cell its centroid within epsilon of the plane, or within its planarity bound (2.5
// times the sensor's noise at its range) where that is wider (its RMS is the sensor's noise, and
// its own fit too poor to say how much of the RMS the model plane adds). Beyond ~4 m a flat
// wall's cell centroids scatter by more than epsilon about its plane (disparity terraces ~70 mm
// deep at 5 m): with epsilon alone a corridor's side walls 4.5-5.8 m ahead broke into 12 planes
// each, 4-18 degrees off, and left and right came out 15 degrees from parallel.
bool joins(const CellFit& f, const GrowthPlane& plane, double cos_angle, double eps2) {
  if (!f.planar || f.block_normal.dot(plane.mean_normal) < cos_angle) return false;
  const double off = plane.n.dot(f.mean) + plane.d;
  const double off2 = off * off;
  if (f.quiet) {
    return f.mse_to(plane.n, plane.d) <= eps2 &&
           off2 <= std::max(f.max_mse, kCorrelatedNoise * kCorrelatedNoise * f.mse);
  }
  return off2 <= std::max(eps2, f.max_mse);
}

constexpr int kMaxNeighbours = 8;

struct GrownRegion {
  Eigen::Vector3d normal;  // least-squares, unit, facing like the mean normal
  bool has_quiet_cell = false;
  // Kept planes with a cell beside the region (the first kMaxNeighbours of them).
  std::int32_t neighbours[kMaxNeighbours];
  int neighbour_count = 0;

  void add_neighbour(std::int32_t id) {
    if (neighbour_count < kMaxNeighbours &&
        std::find(neighbours, neighbours + neighbour_count, id) == neighbours + neighbour_count)
      neighbours[neighbour_count++] = id;
  }
};

// Grows a region from `seed`; returns with its cells in s.queue and all their points in `model`.
// In a region seeded by a quiet cell, noisy cells join the region but not its plane: their
// points go into `model` only when the growth is over, so they neither tilt the plane the
// tests use nor the reported normal.
GrownRegion grow_region(const CellGrid& grid, int seed, std::int32_t id, double eps2, double eps,
                        CellGrowingScratch& s, PlaneModel& model) {
  GrownRegion region;
  PlaneModel& noisy = s.noisy_cells;
  noisy = PlaneModel();
  const bool quiet_seed = grid.cells[seed].quiet;
  const auto join = [&](int c) {
    const CellFit& f = grid.cells[c];
    (quiet_seed && !f.quiet ? noisy : model).add_moments(f.count, f.sum_p, f.sum_pp, f.sum_z3, f.block_normal);
    region.has_quiet_cell |= f.quiet;
    s.cell_labels[c] = id;
    s.queue.push_back(c);
  };
  s.queue.clear();
  model = PlaneModel();
  join(seed);
  GrowthPlane plane;
  plane.noisy_seed = !quiet_seed;
  if (quiet_seed) plane.n = grid.cells[seed].normal, plane.fitted_cells = 1;  // its fit: no eigen-solve
  plane.update(model, 1);
  for (std::size_t head = 0; head < s.queue.size(); ++head) {
    const int c = s.queue[head];
    const int cu = c % grid.cols, cv = c / grid.cols;
    const int next[4] = {cu > 0 ? c - 1 : -1, cu + 1 < grid.cols ? c + 1 : -1, cv > 0 ? c - grid.cols : -1,
                         cv + 1 < grid.rows ? c + grid.cols : -1};
    for (int nb : next) {
      if (nb < 0) continue;
      if (s.cell_labels[nb] != 0) {
        if (s.cell_labels[nb] != id) region.add_neighbour(s.cell_labels[nb]);
        continue;
      }
      const CellFit& f = grid.cells[nb];
      if (!joins(f, plane, s.cos_angle[nb], eps2) || !continuous(grid.cells[c], f, plane.n, eps)) continue;
      join(nb);
      plane.update(model, s.queue.size());  // eq. 4 after every join
    }
  }
  if (plane.fitted_cells != s.queue.size()) plane.refit(model);
  if (plane.n.dot(model.sum_normal()) < 0) plane.n = -plane.n;
  if (noisy.count() > 0) model.merge(noisy);
  region.normal = plane.n;
  return region;
}

// Rewrites label `from` as `to` inside the tally's box (which holds all of that plane's pixels).
void relabel_in_box(const PixelTally& t, std::int32_t from, std::int32_t to, PlaneSegments& out) {
  for (int v = t.v0; v <= t.v1; ++v) {
    std::int32_t* row = out.labels.data() + static_cast<std::size_t>(v) * out.width;
    for (int u = t.u0; u <= t.u1; ++u)
      if (row[u] == from) row[u] = to;
  }
}

// A region is the seam between two kept planes beside it, not a surface, when the two of them
// are each the nearest plane within epsilon for at least a quarter of its points and together
// for kSeamShare of them. Where a zone plate's step crosses cells, those cells hold both sides:
// their block normals tilt by 5-9 degrees while claiming 0.5, they join neither plate and grow a
// strip of their own along the step, half one plate and half the other (measured on the field
// preset: 16 of 409 planes, 13 degrees off the wall). Left free, their pixels go to the nearer
// plate one by one (assign_cell_pixels).
constexpr double kSeamShare = 0.9;

// `region` holds `count` points (all valid pixels of its cells, in s.queue).
bool is_seam(const GrownRegion& region, long count, const CellGrid& grid, double eps, const CellGrowingScratch& s) {
  const int n = region.neighbour_count;
  const std::int32_t* ids = region.neighbours;
  if (n < 2) return false;
  // Each cell to the plane its points lie nearest to (RMS, exact from its moments), when within
  // epsilon. Per pixel it gained 0.2-0.7 points of precision but cost 0.7 ms on cape's frame
  // (the cloud's rows of scattered cells miss the cache).
  const double eps2 = eps * eps;
  long taken[kMaxNeighbours] = {0, 0, 0, 0, 0, 0, 0, 0}, apart = 0;
  const long max_apart = static_cast<long>((1.0 - kSeamShare) * static_cast<double>(count));
  Eigen::Vector3d normals[kMaxNeighbours];
  for (int k = 0; k < n; ++k) normals[k] = s.assign_planes[ids[k] - 1].head<3>().cast<double>();
  for (const std::int32_t cell : s.queue) {
    const CellFit& f = grid.cells[cell];
    int best = -1;
    double best_mse = eps2;
    for (int k = 0; k < n; ++k) {
      const double mse = f.mse_to(normals[k], s.assign_planes[ids[k] - 1].w());
      if (mse <= best_mse) best = k, best_mse = mse;
    }
    if (best >= 0) taken[best] += f.count;
    else if ((apart += f.count) > max_apart) return false;
  }
  long first = 0, second = 0;
  for (int k = 0; k < n; ++k) {
    if (taken[k] > first) second = first, first = taken[k];
    else if (taken[k] > second) second = taken[k];
  }
  return 4 * second >= count && static_cast<double>(first + second) >= kSeamShare * static_cast<double>(count);
}

// A plane that (nearly) contains the camera's centre is no surface: pixels smeared along their
// rays across a depth edge (flying pixels, between a diaphragm's manhole rim and the wall behind
// it) line up into such planes, within 0.3-0.8 degrees of edge-on. A surface seen that close to
// edge-on gives the sensor no depth to measure.
constexpr double kMinSightlineDeg = 1.5;

bool contains_the_sightlines(const PlaneSegment& plane) {
  const double distance = plane.centroid.norm();
  return std::abs(plane.offset_m) < std::sin(kMinSightlineDeg * M_PI / 180.0) * distance;
}

// The tilt (radians) that depth noise along the rays gives the least-squares normal `n` of the
// points in `m` (errors in variables, disparity_fit.h): the noise adds sigma_z^2 q q^T (q = p/z,
// sigma_z = c z^2) to the points' covariance C, which turns n by C^-1 of that term's in-plane
// part. Taken at the centroid: a first-order estimate to decide where the fit is worth redoing.
double predicted_depth_noise_tilt(const PlaneModel& m, const Eigen::Vector3d& n, double noise_per_m2) {
  const Eigen::Vector3d p = m.mean_point();
  if (!(p.z() > 0) || noise_per_m2 <= 0) return 0.0;
  const Eigen::Vector3d q = p / p.z();
  const double sigma = noise_per_m2 * p.z() * p.z();
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  const Eigen::Matrix3d c = m.covariance();
  const Eigen::Vector3d ct1 = c * t1, ct2 = c * t2;
  const double a = t1.dot(ct1), b = t1.dot(ct2), d = t2.dot(ct2);
  const double det = a * d - b * b;
  const double s = sigma * sigma * n.dot(q);
  const double r1 = s * t1.dot(q), r2 = s * t2.dot(q);
  if (!(det > 0)) return M_PI;
  const double x1 = (d * r1 - b * r2) / det, x2 = (a * r2 - b * r1) / det;
  return std::sqrt(x1 * x1 + x2 * x2);
}

// The region's plane normal as reported: its least-squares normal, or where depth noise tilts
// that by more than kMaxNoiseTilt, the disparity-space fit of its points (disparity_fit.h).
// Measured on the walk to 1.8 m from a diaphragm: a floor sliver at 3.4 m came out 5.2
// degrees off by least squares and 1.1 by disparity. The pass over the region's pixels costs
// 0.1-0.3 ms on the real frames (their rows miss the cache), spent only where the tilt is
// predicted: below 1e-3 rad, the fitted normal stands.
constexpr double kMaxNoiseTilt = 1e-3;  // radians

Eigen::Vector3d reported_normal(const OrganizedCloud& cloud, const CellGrid& grid, const std::vector<std::int32_t>& cells,
                                const PlaneModel& model, const Eigen::Vector3d& least_squares) {
  if (predicted_depth_noise_tilt(model, least_squares, grid.noise_per_m2) <= kMaxNoiseTilt) return least_squares;
  DisparityMoments m;
  add_cell_points(cloud, grid, cells, m);
  Eigen::Vector3d n;
  double d;
  if (!m.plane(n, d)) return least_squares;
  return n.dot(least_squares) < 0 ? Eigen::Vector3d(-n) : n;
}

}  // namespace

void extract_planes_by_cells(const OrganizedCloud& cloud, const GrowOptions& options, PlaneSegments& out,
                             CellGrowingScratch& s, ContourBufferPool& pool) {
  out.width = cloud.width;
  out.height = cloud.height;
  const std::size_t n = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (cloud.points.size() != n || n == 0) {
    shrink_plane_slots(out.planes, 0, pool);
    out.labels.assign(n, 0);
    return;
  }
  const int c = std::max(2, options.cell_px);
  const double eps = options.distance_m;
  // A cell is quiet when its own fit leaves its points within epsilon/2 on RMS (the rest of
  // epsilon is the room for the noise of the region's model), with half its pixels valid; a
  // farther cell whose RMS is the sensor's noise at its range is planar too (noisy).
  StageTimer fits_timer(out.timings_ms, "cell_fits");
  compute_cell_fits(cloud, c, (c * c + 1) / 2, 0.5 * eps, s.grid, kNoiseMultiple);
  fits_timer.stop();
  StageTimer block_timer(out.timings_ms, "block_normals");
  smooth_cell_normals(s.grid);
  block_timer.stop();
  StageTimer grow_timer(out.timings_ms, "grow");
  const CellGrid& grid = s.grid;
  const std::size_t cells = grid.cells.size();
  s.cell_labels.assign(cells, 0);
  s.seeded.assign(cells, 0);
  order_seeds(grid, 0.25 * eps * eps, s);

  // Eq. 2's lambda bounds the angle between two directions known exactly; a cell's normal is
  // known to its standard error, so the bound widens by twice that (a cell of pure noise on the
  // plane passes 95 % of the time).
  s.cos_angle.resize(cells);
  const double lambda = options.angle_deg * M_PI / 180.0;
  for (std::size_t i = 0; i < cells; ++i)  // only planar cells are ever tested
    s.cos_angle[i] = grid.cells[i].planar
                         ? cos_to_right_angle(std::min(0.5 * M_PI, lambda + kAngleErrors * grid.cells[i].block_se))
                         : 2.0;
  const double eps2 = eps * eps;
  const double fxfy = cloud.intrinsics.fx * cloud.intrinsics.fy;
  std::size_t kept = 0;
  std::int32_t next_id = 1;
  PlaneModel model;
  for (const std::int32_t seed : s.seeds) {
    if (s.cell_labels[seed] != 0 || s.seeded[seed]) continue;
    const GrownRegion region = grow_region(grid, seed, next_id, eps2, eps, s, model);
    for (const std::int32_t q : s.queue) s.seeded[q] = 1;
    bool keep = model.count() >= options.min_points &&
                (region.has_quiet_cell || s.queue.size() >= kMinNoisyRegionCells) &&
                !is_seam(region, model.count(), grid, eps, s);
    if (keep) {
      if (kept == out.planes.size()) add_plane_slot(out.planes, pool);
      // A region too small with its least-squares normal is not refitted: the disparity fit
      // turns a normal away from grazing, which shrinks the area (a third of the refits saved
      // on the office frame).
      fill_segment_statistics(out.planes[kept], model, options, fxfy, region.normal);
      keep = out.planes[kept].area_m2 >= options.min_area_m2;
      if (keep) {
        const Eigen::Vector3d normal = reported_normal(cloud, grid, s.queue, model, region.normal);
        if (normal != region.normal) {
          fill_segment_statistics(out.planes[kept], model, options, fxfy, normal);
          keep = out.planes[kept].area_m2 >= options.min_area_m2;
        }
      }
      keep = keep && !contains_the_sightlines(out.planes[kept]);
    }
    if (!keep) {  // free again for later regions, but never a seed
      for (const std::int32_t q : s.queue) s.cell_labels[q] = 0;
      continue;
    }
    PlaneSegment& plane = out.planes[kept];
    plane.id = next_id;
    if (s.assign_planes.size() <= kept) s.assign_planes.resize(kept + 1), s.tallies.resize(kept + 1);
    s.assign_planes[kept] << plane.normal.cast<float>(), static_cast<float>(plane.offset_m);
    s.tallies[kept] = PixelTally();
    ++kept;
    ++next_id;
  }
  shrink_plane_slots(out.planes, kept, pool);
  grow_timer.stop();
  StageTimer assign_timer(out.timings_ms, "assign");
  assign_cell_pixels(cloud, grid, eps, s.cell_labels, s.assign_planes, s.tallies, out);
  // A plane whose border pixels all went to its neighbours and that fell below the minimum is
  // dropped: the last plane takes its slot and id, so only the two planes' boxes are relabelled
  // (closing the ids up in order rewrote the whole image, 0.07 ms on the office frame).
  std::size_t now = kept;
  for (std::size_t i = 0; i < now;) {
    if (s.tallies[i].count >= options.min_points) {
      ++i;
      continue;
    }
    relabel_in_box(s.tallies[i], static_cast<std::int32_t>(i + 1), 0, out);
    if (i != --now) {
      relabel_in_box(s.tallies[now], static_cast<std::int32_t>(now + 1), static_cast<std::int32_t>(i + 1), out);
      std::swap(out.planes[i], out.planes[now]);
      std::swap(s.tallies[i], s.tallies[now]);
    }
  }
  for (std::size_t i = 0; i < now; ++i) {
    const PixelTally& all = s.tallies[i];
    PlaneSegment& plane = out.planes[i];
    // The plane itself (normal, offset, RMS) stays the grown cells' fit: those passed the eq. 2
    // tests as wholes, while border pixels near a corner pass the distance test for both
    // planes and would tilt the fit. Points, centroid and area count every assigned pixel.
    plane.points = static_cast<int>(all.count);
    plane.centroid = all.sum_p / static_cast<double>(all.count);
    plane.area_m2 = std::abs(plane.offset_m) > 1e-9 ? all.sum_z3 / (fxfy * std::abs(plane.offset_m)) : 0.0;
    plane.bbox_u0 = all.u0, plane.bbox_v0 = all.v0, plane.bbox_u1 = all.u1, plane.bbox_v1 = all.v1;
    plane.id = static_cast<int>(i + 1);
  }
  shrink_plane_slots(out.planes, now, pool);
}

}  // namespace tunnelmap
