#include "core/mapping/slam_patches.h"

#include "core/mapping/wall_zone_layers.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

namespace tunnelmap {

namespace {

struct Moments {
  double weight = 0.0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  int blocks = 0;
  double max_depth_m = 0.0;
  void add(const Eigen::Vector3d& p, double w) {
    weight += w;
    sum += w * p;
    outer += w * p * p.transpose();
    ++blocks;
    max_depth_m = std::max(max_depth_m, p.z());
  }
};

// Depth beyond the cloud's range is dropped pixel by pixel, so a plate near that range keeps
// only its pixels whose noise brought them nearer: its plane comes out too near, by a good
// part of the noise (on a 4.9 m plate with 5 m range, 35 mm: the map of a girder shrank by
// 2 mm per metre). A plate is kept only when its farthest part lies this many standard
// deviations of its pixels' noise inside the range (the bias is then below 1 % of it).
constexpr double kRangeMarginSigmas = 3.0;

bool cut_by_range(double max_depth_m, double pixel_sigma_m, double cloud_max_range_m) {
  return max_depth_m + kRangeMarginSigmas * pixel_sigma_m > cloud_max_range_m;
}

// The scatter of one pixel of a patch about its plane, from its blocks' means (a block mean of n
// pixels scatters by sigma / sqrt(n)).
double pixel_scatter_m(const Moments& m, double normal_variance) {
  return m.blocks > 0 ? std::sqrt(std::max(0.0, normal_variance) * m.weight / m.blocks) : 0.0;
}

// The same from the moments alone.
double pixel_scatter_m(const Moments& m) {
  const Eigen::Vector3d centroid = m.sum / m.weight;
  const Eigen::Matrix3d cov = m.outer / m.weight - centroid * centroid.transpose();
  return pixel_scatter_m(m, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues()[0]);
}

// Each plate across the axis that the frame saw, by plane id: kept or dropped whole, as a cut
// per point biases it.
std::map<int, Moments> plate_moments(const FrameWalls& walls) {
  std::map<int, Moments> plates;
  for (const WallSample& s : walls.samples)
    if (s.wall == kTransverseSample) plates[s.plane].add(s.point.cast<double>(), s.points);
  return plates;
}

// One pixel's noise: the sensor model at the patch's farthest depth, or its scatter if larger
// (the segmentation keeps the pixels near each plane, so the scatter alone falls short of the
// noise on far plates).
double pixel_sigma_m(const Moments& m, double scatter_m, double point_sigma_m) {
  return std::max(scatter_m, point_sigma_m * m.max_depth_m * m.max_depth_m);
}

// What a patch keeps of the depth's quantisation. The noise that comes before the rounding
// dithers it: the mean of many rounded readings of one depth is off by a periodic function of
// where that depth falls between two steps, whose k-th harmonic has the amplitude
// step / (pi k) exp(-2 pi^2 k^2 sigma^2 / step^2) for Gaussian noise sigma. Over depths that
// fall anywhere between steps, the RMS of the sum; without noise it is a step's whole error,
// step / sqrt(12) (a plate seen head-on, its points all on one step); noise of half a step
// leaves under 1 % of it. A patch that runs through many steps (a wall seen along its length)
// averages it further over the steps it spans. The dither is the patch's own scatter, never
// the sensor model: a camera with steps and little noise keeps its steps' whole error.
double quantisation_sigma_m(double step_m, double pixel_scatter_m, const Eigen::Matrix3d& camera_cov) {
  if (!(step_m > 0.0)) return 0.0;
  // The scatter includes the rounding's own (step^2 / 12); only the rest dithers.
  const double dither_var = std::max(0.0, pixel_scatter_m * pixel_scatter_m - step_m * step_m / 12.0);
  const double damping = 2.0 * M_PI * M_PI * dither_var / (step_m * step_m);
  double mean_square = 0.0;
  for (int k = 1; k <= 64; ++k) {
    const double amplitude = step_m / (M_PI * k) * std::exp(-damping * k * k);
    mean_square += 0.5 * amplitude * amplitude;
    if (amplitude < 1e-4 * step_m) break;
  }
  const double depth_span = std::sqrt(12.0 * std::max(0.0, camera_cov(2, 2)));
  const double steps = std::max(1.0, depth_span / step_m);
  return std::sqrt(mean_square / steps);
}

// Centroid, in-plane spread and the patch's own normal; the scatter along that normal (the
// points' noise) is left out, so that a patch lying exactly on its landmark has no residual.
bool reduce(const Moments& m, const SlamOptions& o, FramePatch& out) {
  if (m.weight < o.min_patch_points) return false;
  out.points = static_cast<int>(m.weight);
  out.centroid = m.sum / m.weight;
  const Eigen::Matrix3d cov = m.outer / m.weight - out.centroid * out.centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  out.spread.setZero();
  for (int k = 1; k < 3; ++k)
    out.spread.col(k - 1) = eig.eigenvectors().col(k) * std::sqrt(std::max(0.0, eig.eigenvalues()[k]));
  out.normal = eig.eigenvectors().col(0);  // the fitted plane's (either way); callers orient it
  // Structured light's depth error grows with z^2, and part of it does not average out over a
  // patch: the floor grows alike, and so does the depth step.
  const double z = out.centroid.norm();
  const double growth = std::max(1.0, z * z);
  const double point_sigma = o.point_sigma_m * growth, floor = o.patch_floor_m * growth;
  const double scatter = pixel_scatter_m(m, eig.eigenvalues()[0]);
  out.pixel_sigma_m = pixel_sigma_m(m, scatter, o.point_sigma_m);
  const double step = quantisation_sigma_m(o.depth_step_m * z * z, scatter, cov);
  out.sigma_m = std::sqrt(point_sigma * point_sigma / m.weight + floor * floor + step * step);
  return true;
}

// A block sample's noise along its wall's normal: the depth's noise and steps at its depth
// move it along its ray (a depth error e moves it by p e / z), which meets a wall seen at a
// grazing angle almost along the wall.
double sample_sigma_m(const WallSample& s, const Eigen::Vector3d& outward, const SlamOptions& o) {
  const Eigen::Vector3d p = s.point.cast<double>();
  const double z2 = p.z() * p.z();
  const double step = o.depth_step_m * z2, noise = o.point_sigma_m * z2;
  const double along_normal = std::abs(outward.dot(p)) / std::max(1e-6, p.z());
  return std::sqrt(noise * noise + step * step / 12.0) * along_normal / std::sqrt(std::max(1, s.points));
}

// A frame's cross-section parts whose walls do not step are one surface: the frame splits
// where its sections seem to change, and on a girder of one section it does so at a sixth of
// its frames. Per (wall, part), the first part of that wall whose outer surface lies within
// half a section change (`FrameWallsOptions::section_change_m`) of it.
std::map<std::pair<int, int>, int> wall_surfaces(const TunnelMap& map, const std::vector<const WallSample*>& samples) {
  std::map<std::pair<int, int>, std::vector<double>> outer;  // each sample's outer surface
  for (const WallSample* s : samples)
    outer[{s->wall, s->part}].push_back(s->inset_m - map.walls[s->wall].normal.dot(s->point.cast<double>()));
  std::map<std::pair<int, int>, double> median;
  for (auto& [key, v] : outer) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    median[key] = v[v.size() / 2];
  }
  const double same = 0.5 * FrameWallsOptions().section_change_m;
  std::map<std::pair<int, int>, int> surface;
  for (const auto& [key, position] : median) {
    int first = key.second;
    for (const auto& [other, other_position] : median)
      if (other.first == key.first && other.second < first && std::abs(other_position - position) < same)
        first = other.second;
    surface[key] = first;
  }
  return surface;
}

using BandKey = std::tuple<int, long, float>;  // (wall, band, inset)

// The frame's wall samples by wall, band and zone: the zones of one wall stay apart, each
// sample on the layer its own position says (core/mapping/wall_zone_layers.h); which of them
// is the outer surface the frame may misjudge.
std::map<BandKey, Moments> wall_bands(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                      const Eigen::Vector3d& axis_cam, const SlamOptions& o, const WallBandGrid& grid) {
  std::vector<const WallSample*> kept;
  for (const WallSample& s : walls.samples) {
    if (s.wall >= 4 || !s.on_surface || s.point.z() > o.max_wall_depth_m) continue;
    if (map.walls[s.wall].normal.squaredNorm() < 0.5) continue;
    kept.push_back(&s);
  }
  // Per wall and cross-section part where the wall steps (a joint in view): its zones are
  // layers of one part's wall.
  const std::map<std::pair<int, int>, int> surface = wall_surfaces(map, kept);
  std::map<std::pair<int, int>, std::vector<const WallSample*>> on_wall;
  std::map<std::pair<int, int>, std::vector<LayerSample>> layer_samples;
  for (const WallSample* s : kept) {
    const std::pair<int, int> key{s->wall, surface.at({s->wall, s->part})};
    on_wall[key].push_back(s);
    layer_samples[key].push_back({s->point.cast<double>(), sample_sigma_m(*s, -map.walls[s->wall].normal, o), s->inset_m});
  }
  std::map<BandKey, Moments> bands;
  for (const auto& [key, samples] : layer_samples) {
    const int c = key.first;
    const std::vector<double> insets = wall_zone_layers(samples, -map.walls[c].normal, axis_cam);
    for (std::size_t i = 0; i < insets.size(); ++i) {
      if (std::isnan(insets[i])) continue;
      const Eigen::Vector3d& p = samples[i].point;
      bands[{c, grid.band(camera_station_m + axis_cam.dot(p)), static_cast<float>(insets[i])}].add(p, on_wall[key][i]->points);
    }
  }
  return bands;
}

}  // namespace

std::vector<FramePatch> frame_wall_patches(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                           const Eigen::Vector3d& axis_cam, const SlamOptions& o,
                                           const WallBandGrid& grid) {
  const std::map<BandKey, Moments> bands = wall_bands(map, walls, camera_station_m, axis_cam, o, grid);
  bool has_inner[4] = {false, false, false, false};
  for (const auto& [key, m] : bands)
    if (std::get<2>(key) > kMinZoneStepM && m.weight >= o.min_patch_points) has_inner[std::get<0>(key)] = true;
  std::vector<FramePatch> out;
  for (const auto& [key, m] : bands) {
    FramePatch patch;
    if (!reduce(m, o, patch)) continue;
    patch.wall = std::get<0>(key);
    patch.band = std::get<1>(key);
    const bool inner = std::get<2>(key) > kMinZoneStepM;
    if (inner) patch.zone = FramePatch::Zone::Inner;
    else if (has_inner[patch.wall]) patch.zone = FramePatch::Zone::Outer;
    patch.normal = -map.walls[patch.wall].normal;
    patch.station_m = camera_station_m + axis_cam.dot(patch.centroid);
    out.push_back(patch);
  }
  return out;
}

std::vector<int> plates_cut_by_range(const FrameWalls& walls, double cloud_max_range_m, double point_sigma_m) {
  std::vector<int> cut;
  for (const auto& [plane, m] : plate_moments(walls))
    if (cut_by_range(m.max_depth_m, pixel_sigma_m(m, pixel_scatter_m(m), point_sigma_m), cloud_max_range_m))
      cut.push_back(plane);
  return cut;
}

std::vector<FramePatch> frame_plate_patches(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                            const Eigen::Vector3d& axis_cam, const SlamOptions& o) {
  const double cos_transverse = std::cos(kTransverseMaxAngleDeg * M_PI / 180.0);
  std::vector<FramePatch> out;
  for (const auto& [plane, m] : plate_moments(walls)) {
    FramePatch patch;
    if (!reduce(m, o, patch) || patch.centroid.z() > o.max_plate_depth_m) continue;
    if (cut_by_range(m.max_depth_m, patch.pixel_sigma_m, o.cloud_max_range_m)) continue;
    if (!map.detected && std::abs(patch.normal.dot(axis_cam)) < cos_transverse) continue;
    patch.plate = true;
    patch.wall = kTransverseSample;
    patch.normal = axis_cam;
    patch.station_m = camera_station_m + axis_cam.dot(patch.centroid);
    out.push_back(patch);
  }
  return out;
}

}  // namespace tunnelmap
