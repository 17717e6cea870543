#include "core/mapping/slam_patches.h"

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

// A wall plane this far inside the outer surface is the middle plate (plates are several
// millimetres thick; the frame's outer surface itself lies within a millimetre).
constexpr double kInnerInsetM = 0.0025;

// The scatter of one pixel of a patch about its plane, from its blocks' means (a block mean of n
// pixels scatters by sigma / sqrt(n)).
double pixel_scatter_m(const Moments& m, double normal_variance) {
  return m.blocks > 0 ? std::sqrt(std::max(0.0, normal_variance) * m.weight / m.blocks) : 0.0;
}

// The noise of one pixel of a patch: the sensor model at its depth, or its scatter if larger.
// The segmentation keeps the pixels near each plane, so the scatter alone falls short of the
// noise on far plates.
double pixel_sigma_m(const Moments& m, double normal_variance, double model_sigma_m) {
  return std::max(pixel_scatter_m(m, normal_variance), model_sigma_m);
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
  // Structured light's depth error grows with z^2, and part of it does not average out over a
  // patch: the floor grows alike, and so does the depth step.
  const double z = out.centroid.norm();
  const double growth = std::max(1.0, z * z);
  const double point_sigma = o.point_sigma_m * growth, floor = o.patch_floor_m * growth;
  out.pixel_sigma_m = pixel_sigma_m(m, eig.eigenvalues()[0], o.point_sigma_m * m.max_depth_m * m.max_depth_m);
  const double step = quantisation_sigma_m(o.depth_step_m * z * z, pixel_scatter_m(m, eig.eigenvalues()[0]), cov);
  out.sigma_m = std::sqrt(point_sigma * point_sigma / m.weight + floor * floor + step * step);
  return true;
}

}  // namespace

std::vector<FramePatch> frame_patches(const TunnelMap& map, const FrameWalls& walls, double camera_station_m,
                                      const Eigen::Vector3d& axis_cam, const SlamOptions& o) {
  // (wall, band, inset): the frame's zones of one wall stay apart (the inset tells them apart
  // within the frame; which of them is the outer surface it may misjudge).
  std::map<std::tuple<int, long, float>, Moments> bands;
  std::map<int, Moments> plates;                   // plane id
  for (const WallSample& s : walls.samples) {
    const Eigen::Vector3d p = s.point.cast<double>();
    if (s.wall == kTransverseSample) {
      plates[s.plane].add(p, s.points);  // kept or dropped whole, below: a cut per point biases it
      continue;
    }
    if (s.wall >= 4 || !s.on_surface || p.z() > o.max_wall_depth_m) continue;
    const Wall& wall = map.walls[s.wall];
    if (wall.normal.squaredNorm() < 0.5) continue;
    const double station = camera_station_m + axis_cam.dot(p);
    bands[{s.wall, static_cast<long>(std::floor(station / o.band_m)), s.inset_m}].add(p, s.points);
  }
  bool has_inner[4] = {false, false, false, false};
  for (const auto& [key, m] : bands)
    if (std::get<2>(key) > kInnerInsetM && m.weight >= o.min_patch_points) has_inner[std::get<0>(key)] = true;
  std::vector<FramePatch> out;
  for (const auto& [key, m] : bands) {
    FramePatch patch;
    if (!reduce(m, o, patch)) continue;
    patch.wall = std::get<0>(key);
    patch.band = std::get<1>(key);
    const bool inner = std::get<2>(key) > kInnerInsetM;
    if (inner) patch.zone = FramePatch::Zone::Inner;
    else if (has_inner[patch.wall]) patch.zone = FramePatch::Zone::Outer;
    patch.normal = -map.walls[patch.wall].normal;
    patch.station_m = camera_station_m + axis_cam.dot(patch.centroid);
    out.push_back(patch);
  }
  for (const auto& [plane, m] : plates) {
    FramePatch patch;
    if (!reduce(m, o, patch) || patch.centroid.z() > o.max_plate_depth_m) continue;
    if (m.max_depth_m + kRangeMarginSigmas * patch.pixel_sigma_m > o.cloud_max_range_m) continue;
    patch.plate = true;
    patch.wall = kTransverseSample;
    patch.normal = axis_cam;
    patch.station_m = camera_station_m + axis_cam.dot(patch.centroid);
    out.push_back(patch);
  }
  return out;
}

}  // namespace tunnelmap
