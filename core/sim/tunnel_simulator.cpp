#include "core/sim/tunnel_simulator.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <thread>
#include <tuple>

#include "core/sim/sensor_model.h"
#include "core/sim/sim_girder.h"
#include "core/sim/sim_random.h"

namespace tunnelmap {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

const SimConfig& validated(const SimConfig& c) {
  c.validate();
  return c;
}

int distance_count(const SimConfig& c) {
  return c.distance_to_manhole_m ? 1 : static_cast<int>(c.manhole_distances_m.size());
}

double distance_at(const SimConfig& c, int group) {
  return c.distance_to_manhole_m ? *c.distance_to_manhole_m
                                 : c.manhole_distances_m[group % c.manhole_distances_m.size()];
}

std::uint8_t to_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

}  // namespace

std::optional<double> TunnelSimulator::compute_manhole_x(const SimConfig& c) { return sim::manhole_plate_x(c); }

std::optional<double> TunnelSimulator::compute_end_x(const SimConfig& c) {
  if (c.girder_length_m) return *c.girder_length_m;
  if (!c.end_wall_distance_m) return std::nullopt;
  const std::optional<double> manhole = compute_manhole_x(c);
  if (!c.walk) return manhole.value_or(0.0) + *c.end_wall_distance_m;
  // A walk must not run into the end wall: beyond its furthest station (or the plate).
  double x = std::max(c.walk->start_x_m, c.walk->end_x_m);
  if (manhole) x = std::max(x, *manhole);
  return x + *c.end_wall_distance_m;
}

TunnelSimulator::TunnelSimulator(SimConfig config)
    : config_(validated(config)),
      sections_(config_),
      manhole_x_(compute_manhole_x(config_)),
      geometry_(config_, manhole_x_, compute_end_x(config_)) {
  plates_x_ = diaphragms_x();
  groups_ = config_.walk
                ? config_.walk->stops
                : std::max(static_cast<int>(config_.poses.size()), distance_count(config_));
  if (config_.walk && config_.walk->look_back) {
    std::vector<double> stop_x;
    for (int g = 0; g < groups_; ++g) stop_x.push_back(group_x(g));
    looks_back_ = sim::look_back_stops(stop_x, plates_x_);
  }
  if (config_.has_drift()) make_drift();
}

Eigen::Isometry3d SimDrift::apply(const Eigen::Isometry3d& T) const {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = rotation * T.linear();
  out.translation() = T.translation() + translation;
  return out;
}

void TunnelSimulator::make_drift() {
  // A random walk over the nominal camera positions of the pose groups, in group order.
  sim::SimRandom rng(config_.seed, sim::kStreamDrift, 0);
  const double st = config_.drift_translation_mm_per_sqrt_m / 1000.0;
  const double sr = config_.drift_rotation_deg_per_sqrt_m * kDeg;
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  drift_.assign(groups_, SimDrift{});
  travelled_.assign(groups_, 0.0);
  Eigen::Vector3d prev = group_pose(0, zero).translation();
  for (int g = 1; g < groups_; ++g) {
    const Eigen::Vector3d here = group_pose(g, zero).translation();
    const double ds = (here - prev).norm();
    prev = here;
    travelled_[g] = travelled_[g - 1] + ds;
    const double k = std::sqrt(ds);
    SimDrift d = drift_[g - 1];
    Eigen::Vector3d dt, dr;  // drawn in a fixed order (argument order is unspecified)
    for (int a = 0; a < 3; ++a) dt[a] = rng.normal();
    for (int a = 0; a < 3; ++a) dr[a] = rng.normal();
    d.translation += st * k * dt;
    const Eigen::Vector3d w = sr * k * dr;
    if (w.norm() > 0.0) d.rotation = Eigen::AngleAxisd(w.norm(), w.normalized()) * d.rotation;
    drift_[g] = d;
  }
}

const SimDrift& TunnelSimulator::drift(int group) const {
  static const SimDrift kNone;
  return drift_.empty() ? kNone : drift_.at(group);
}

std::pair<Eigen::Isometry3d, Eigen::Isometry3d> TunnelSimulator::reported(
    int group, const Eigen::Isometry3d& T, const std::optional<SimArmState>& arm) const {
  if (!arm) return {drift_.empty() ? T : drift(group).apply(T), Eigen::Isometry3d::Identity()};
  if (drift_.empty()) return {arm->fk_pose, arm->base};
  // Odometry drifts the base; the joints then place the camera from there (without sag).
  const Eigen::Isometry3d base = drift(group).apply(arm->base);
  return {base * (arm->base.inverse() * arm->fk_pose), base};
}

Eigen::Isometry3d TunnelSimulator::reported_pose(int index) const {
  const std::optional<SimArmState> arm = arm_state(index);
  return reported(pose_group(index), arm ? arm->true_pose : wanted_pose(index), arm).first;
}

std::vector<double> TunnelSimulator::diaphragms_x() const {
  std::vector<double> x = sim::diaphragm_stations(config_);
  if (manhole_x_) x.push_back(*manhole_x_);
  std::sort(x.begin(), x.end());
  return x;
}

const SimSurface* TunnelSimulator::surface(int id) const {
  for (const SimSurface& s : surfaces())
    if (s.id == id) return &s;
  return nullptr;
}

int TunnelSimulator::pose_group(int index) const {
  return static_cast<int>(static_cast<long long>(index) * groups_ / config_.frames);
}

std::optional<double> TunnelSimulator::distance_to_manhole(int index) const {
  if (config_.walk) {
    if (!manhole_x_) return std::nullopt;
    const double d = *manhole_x_ - group_x(pose_group(index));
    if (d > 0.0) return d;
    return std::nullopt;
  }
  if (distance_count(config_) == 0) return std::nullopt;
  return distance_at(config_, pose_group(index));
}

Eigen::Matrix3d TunnelSimulator::camera_rotation(double roll_deg, double pitch_deg,
                                                 double yaw_deg) {
  Eigen::Matrix3d look_from_cam;  // columns: camera x, y, z in the look frame (X fwd, Y left, Z up)
  look_from_cam << 0, 0, 1,
                  -1, 0, 0,
                   0, -1, 0;
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(-pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return turn * look_from_cam;
}

double TunnelSimulator::group_x(int g) const {
  if (config_.walk) {
    // Stations evenly spaced from start to end (one stop: at the start).
    const SimWalk& w = *config_.walk;
    if (w.stops <= 1) return w.start_x_m;
    if (g >= w.stops - 1) return w.end_x_m;  // exactly, not start + (end - start)
    return w.start_x_m + (w.end_x_m - w.start_x_m) * g / (w.stops - 1);
  }
  return manhole_x_ ? *manhole_x_ - distance_at(config_, g) : 0.0;
}

Eigen::Isometry3d TunnelSimulator::pose(int index) const {
  if (config_.arm_preset.empty()) return wanted_pose(index);
  return arm_state(index)->true_pose;
}

std::optional<SimArmState> TunnelSimulator::arm_state(int index) const {
  if (config_.arm_preset.empty()) return std::nullopt;
  return solve_sim_arm(config_, group_x(pose_group(index)), wanted_pose(index));
}

Eigen::Isometry3d TunnelSimulator::wanted_pose(int index) const {
  sim::SimRandom rng(config_.seed, static_cast<std::uint32_t>(index), sim::kStreamPose);
  const double jt = config_.jitter_translation_m, jr = config_.jitter_rotation_deg;
  double j[6];
  for (int k = 0; k < 3; ++k) j[k] = rng.normal() * jt;
  for (int k = 3; k < 6; ++k) j[k] = rng.normal() * jr;
  return group_pose(pose_group(index), j);
}

Eigen::Isometry3d TunnelSimulator::group_pose(int g, const double j[6]) const {
  const SimCameraPose& p =
      config_.walk ? config_.walk->pose : config_.poses[g % config_.poses.size()];
  const double x = group_x(g);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = camera_rotation(p.roll_deg + config_.roll_deg + j[3],
                               p.pitch_deg + config_.pitch_deg + j[4],
                               p.yaw_deg + config_.yaw_deg + j[5] + (looks_back(g) ? 180.0 : 0.0));
  // Relative to the cross-section of the section the station is in.
  if (config_.walk && config_.walk->through_openings && !plates_x_.empty()) {
    // Towards the opening's centre near a plate (sim_girder.h).
    const auto it = std::lower_bound(plates_x_.begin(), plates_x_.end(), x);
    double d = std::numeric_limits<double>::infinity();
    if (it != plates_x_.end()) d = *it - x;
    if (it != plates_x_.begin()) d = std::min(d, x - *std::prev(it));
    const double w = sim::opening_weight(d);
    const double H = height_at(x);
    T.translation() = Eigen::Vector3d(
        x + j[0], (1.0 - w) * p.y_rel * width_at(x) + j[1],
        (1.0 - w) * p.z_rel * H + w * sim::opening_centre_z(config_, H) + j[2]);
  } else {
    T.translation() =
        Eigen::Vector3d(x + j[0], p.y_rel * width_at(x) + j[1], p.z_rel * height_at(x) + j[2]);
  }
  // Local (station) frame -> world on a curved girder.
  return geometry_.alignment().to_world(T);
}

SimFrame TunnelSimulator::render(int index) const {
  const Intrinsics K = Intrinsics::primesense_vga();
  SimFrame out;
  out.frame = DepthFrame::blank_mm(K);
  DepthFrame& f = out.frame;
  f.rgb.assign(static_cast<std::size_t>(K.width) * K.height * 3, 0);
  out.arm = arm_state(index);
  const Eigen::Isometry3d T = out.arm ? out.arm->true_pose : pose(index);
  f.pose = T;
  if (out.arm) f.joints = out.arm->joints;
  f.timestamp_s = index * config_.frame_interval_s;
  f.source = "simulated " + config_.preset + " frame " + std::to_string(index);
  out.surface_id.assign(static_cast<std::size_t>(K.width) * K.height, 0);
  out.pose_group = pose_group(index);
  out.distance_to_manhole_m = distance_to_manhole(index);
  std::tie(out.reported_pose, out.reported_base) = reported(out.pose_group, T, out.arm);

  // Rows are independent (each has its own random stream), so threads do not change the result.
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, 4);
  const bool tof = config_.noise_model == "tof";
  std::vector<float> ideal;
  if (tof) ideal.assign(static_cast<std::size_t>(K.width) * K.height, 0.0f);
  std::vector<float>* ideal_out = tof ? &ideal : nullptr;
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k)
    pool.emplace_back([&, k] { render_rows(index, T, k, threads, out, ideal_out); });
  render_rows(index, T, 0, threads, out, ideal_out);
  for (std::thread& t : pool) t.join();
  if (tof && config_.noise_scale > 0.0 && config_.tof_flying_pixel_probability > 0.0)
    flying_pixels(index, ideal, out);
  return out;
}

void TunnelSimulator::flying_pixels(int index, const std::vector<float>& ideal,
                                    SimFrame& out) const {
  // A ToF pixel whose footprint straddles a depth edge returns a mix of both depths: with
  // probability p, a measured pixel next to a jump of more than the threshold (to the
  // 4-neighbour with the largest jump) takes a*own + (1-a)*neighbour, a ~ U(0, 1).
  const SimConfig& c = config_;
  const int W = out.frame.width, H = out.frame.height;
  const std::vector<float> measured = out.frame.depth;  // the pass reads the unmixed depths
  for (int v = 0; v < H; ++v) {
    sim::SimRandom rng(c.seed, static_cast<std::uint32_t>(index),
                       sim::kStreamFlyingBase + static_cast<std::uint32_t>(v));
    for (int u = 0; u < W; ++u) {
      const std::size_t idx = static_cast<std::size_t>(v) * W + u;
      const float z0 = ideal[idx];
      if (measured[idx] <= 0.0f || z0 <= 0.0f) continue;
      double jump = 0.0, zn = 0.0;
      const int du[4] = {-1, 1, 0, 0}, dv[4] = {0, 0, -1, 1};
      for (int k = 0; k < 4; ++k) {
        const int uu = u + du[k], vv = v + dv[k];
        if (uu < 0 || vv < 0 || uu >= W || vv >= H) continue;
        const float zi = ideal[static_cast<std::size_t>(vv) * W + uu];
        if (zi > 0.0f && std::abs(zi - z0) > jump) jump = std::abs(zi - z0), zn = zi;
      }
      if (jump <= c.tof_edge_threshold_m) continue;
      if (rng.uniform() >= c.tof_flying_pixel_probability) continue;
      const double a = rng.uniform();
      const double z = a * measured[idx] / 1000.0 + (1.0 - a) * zn;
      out.frame.depth[idx] = z < c.min_depth_m || z > c.max_depth_m
                                 ? 0.0f
                                 : static_cast<float>(std::min(65535L, std::lround(z * 1000.0)));
    }
  }
}

void TunnelSimulator::render_rows(int index, const Eigen::Isometry3d& T, int row_begin,
                                  int row_step, SimFrame& out, std::vector<float>* ideal) const {
  const SimConfig& c = config_;
  const Intrinsics& K = out.frame.intrinsics;
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d o = T.translation();
  const Eigen::Vector3d cam_z = R.col(2);
  const double ns = c.noise_scale, ds = c.dropout_scale;
  const double p_speckle = std::min(1.0, c.speckle_dropout * ds);
  const double p_rust = std::min(1.0, c.rust_dropout * ds);
  const bool tof = c.noise_model == "tof";

  for (int v = row_begin; v < K.height; v += row_step) {
    sim::SimRandom rng(c.seed, static_cast<std::uint32_t>(index),
                       sim::kStreamRowBase + static_cast<std::uint32_t>(v));
    for (int u = 0; u < K.width; ++u) {
      const std::size_t idx = static_cast<std::size_t>(v) * K.width + u;
      const Eigen::Vector3d dir = (R * K.ray(u, v)).normalized();
      const sim::RayHit hit = geometry_.cast(o, dir);
      out.surface_id[idx] = static_cast<std::uint16_t>(hit.surface_id);
      if (!hit.hit()) continue;
      if (ideal) (*ideal)[idx] = static_cast<float>(hit.t * dir.dot(cam_z));
      const double cos0 = std::clamp(-hit.normal.dot(dir), 0.0, 1.0);
      const bool rust = geometry_.on_rust(hit);

      // Colour: Lambert shading from a light at the camera, inverse-square-ish falloff.
      {
        const double tex = geometry_.texture(hit);
        double alb[3] = {0.55, 0.56, 0.58};  // grey steel
        if (hit.rivet) alb[0] = alb[1] = alb[2] = 0.32;
        else if (rust) alb[0] = 0.50 + 0.08 * tex, alb[1] = 0.27 + 0.05 * tex, alb[2] = 0.12;
        else alb[0] += 0.03 * tex, alb[1] += 0.03 * tex, alb[2] += 0.03 * tex;
        const double light = 0.12 + 1.3 * cos0 / (1.0 + 0.2 * hit.t * hit.t);
        for (int ch = 0; ch < 3; ++ch)
          out.frame.rgb[idx * 3 + ch] = to_byte(alb[ch] * light + 0.01 * rng.normal());
      }

      // Lateral noise: the pixel sees the surface hit by a perturbed ray (edges jitter), but the
      // depth is that surface intersected with the pixel's own ray, so plane interiors are not
      // tilted twice (Nguyen et al.'s axial sigma already includes it).
      sim::RayHit m = hit;
      if (ns > 0.0 && !tof) {
        const double sl = sim::lateral_sigma_px(std::acos(cos0)) * ns;
        const double du = rng.normal() * sl, dv = rng.normal() * sl;
        m = geometry_.cast(o, (R * K.ray(u + du, v + dv)).normalized());
        if (!m.hit()) continue;
      }
      double t = m.t;
      if (m.surface_id != hit.surface_id || m.rivet) {
        if (m.rivet) {
          const Eigen::Vector3d oc = o - m.sphere_center;
          const double b = oc.dot(dir);
          const double disc = b * b - (oc.squaredNorm() - m.sphere_radius * m.sphere_radius);
          t = disc >= 0.0 ? -b - std::sqrt(disc) : -1.0;
          if (t <= 0.0) t = m.point.dot(dir) - o.dot(dir);  // grazing the dome: keep its depth
        } else {
          const double nd = m.normal.dot(dir);
          t = std::abs(nd) > 1e-9 ? -(m.normal.dot(o) + m.plane_offset) / nd : -1.0;
          if (t <= 0.0) t = (m.point - o).dot(dir);
        }
      } else {
        t = hit.t;  // same planar surface: exact depth along the pixel's ray
      }
      const double cos_m = std::clamp(std::abs(m.normal.dot(dir)), 1e-3, 1.0);
      const double theta = std::acos(cos_m);
      double z = t * dir.dot(cam_z);  // depth along the optical axis

      // Rust relief (towards the camera shortens the ray), then axial noise and quantisation.
      const double relief = geometry_.rust_relief_m(m);
      if (relief != 0.0 && ns > 0.0) z -= ns * relief * dir.dot(cam_z) / std::max(cos_m, 0.2);
      if (tof) {
        if (ns > 0.0) z += rng.normal() * ns * sim::tof_sigma_m(z, theta, c.tof_sigma_m, c.tof_sigma_per_m);
      } else {
        if (ns > 0.0) z += rng.normal() * ns * sim::axial_sigma_m(z, theta);
        if (c.quantize_disparity) z = sim::quantize_depth_m(z, K.fx, c.baseline_m, c.subpixel_steps);
      }
      if (z < c.min_depth_m || z > c.max_depth_m) continue;

      // Dropouts: grazing incidence, rust, isolated speckles.
      if (ds > 0.0) {
        const double pg = std::min(1.0, ds * sim::grazing_dropout_probability(
                                                 theta, c.grazing_dropout_start_deg,
                                                 c.grazing_dropout_full_deg));
        const double keep = (1.0 - pg) * (1.0 - p_speckle) * (rust ? 1.0 - p_rust : 1.0);
        if (rng.uniform() >= keep) continue;
      }
      out.frame.depth[idx] = static_cast<float>(std::min(65535L, std::lround(z * 1000.0)));
    }
  }
}

}  // namespace tunnelmap
