#include "core/sim/tunnel_geometry.h"

#include <algorithm>
#include <cmath>

#include "core/sim/sim_random.h"

namespace tunnelmap::sim {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

SimSurface make_surface(int id, const std::string& wall, const std::string& part,
                        const std::string& zone, const Eigen::Vector3d& n, double offset) {
  SimSurface s;
  s.id = id;
  s.wall = wall;
  s.name = part.empty() ? wall : wall + "/" + part;
  s.zone = zone;
  s.normal_world = n;
  s.offset_world = offset;
  return s;
}

}  // namespace

TunnelGeometry::TunnelGeometry(const SimConfig& config, std::optional<double> manhole_x,
                               std::optional<double> end_x)
    : config_(config), manhole_x_(manhole_x), end_x_(end_x) {
  const double W = config.width_m, H = config.height_m, e = config.edge_band_m;
  struct Spec {
    const char* name;
    Eigen::Vector3d n;
    double d_outer;
    Eigen::Vector3d es;
    double s_min, s_max;
    const char *lo, *hi;  // names of the edge bands at s_min / s_max
  };
  const Spec specs[4] = {
      {"left", -Eigen::Vector3d::UnitY(), W / 2, Eigen::Vector3d::UnitZ(), 0.0, H, "bottom", "top"},
      {"right", Eigen::Vector3d::UnitY(), W / 2, Eigen::Vector3d::UnitZ(), 0.0, H, "bottom", "top"},
      {"top", -Eigen::Vector3d::UnitZ(), H, Eigen::Vector3d::UnitY(), -W / 2, W / 2, "right", "left"},
      {"bottom", Eigen::Vector3d::UnitZ(), 0.0, Eigen::Vector3d::UnitY(), -W / 2, W / 2, "right",
       "left"},
  };
  int next_id = 1;
  for (int i = 0; i < 4; ++i) {
    const Spec& sp = specs[i];
    Wall w;
    w.n = sp.n;
    w.d_outer = sp.d_outer;
    w.es = sp.es;
    w.s_min = sp.s_min;
    w.s_max = sp.s_max;
    w.s_mid_lo = sp.s_min + e;
    w.s_mid_hi = sp.s_max - e;
    w.thickness = config.plate_thickness_m[i];
    w.edge_lo_id = next_id++;
    w.middle_id = next_id++;
    w.edge_hi_id = next_id++;
    surfaces_.push_back(make_surface(w.edge_lo_id, sp.name, std::string("edge_") + sp.lo, "edge",
                                     w.n, w.d_outer));
    surfaces_.push_back(
        make_surface(w.middle_id, sp.name, "middle", "middle", w.n, w.d_outer - w.thickness));
    surfaces_.push_back(make_surface(w.edge_hi_id, sp.name, std::string("edge_") + sp.hi, "edge",
                                     w.n, w.d_outer));
    // Rivet rows evenly inside each band, alternate rows staggered by half a pitch.
    const int rows = config.rivet_height_m > 0.0 ? config.rivet_rows_per_band : 0;
    for (int r = 0; r < rows; ++r) {
      const double off = e * (r + 1) / (rows + 1);
      const double phase = (r % 2) * 0.5 * config.rivet_pitch_m;
      w.rivet_row_s.push_back(w.s_min + off);
      w.rivet_row_phase.push_back(phase);
      w.rivet_row_s.push_back(w.s_max - off);
      w.rivet_row_phase.push_back(phase);
    }
    walls_.push_back(w);
  }
  // Step faces after all zones so that zone ids stay 1..12 in wall order.
  for (int i = 0; i < 4; ++i) {
    Wall& w = walls_[i];
    w.step_lo_id = next_id++;
    w.step_hi_id = next_id++;
    surfaces_.push_back(make_surface(w.step_lo_id, specs[i].name, std::string("step_") + specs[i].lo,
                                     "step", -w.es, w.s_mid_lo));
    surfaces_.push_back(make_surface(w.step_hi_id, specs[i].name, std::string("step_") + specs[i].hi,
                                     "step", w.es, -w.s_mid_hi));
  }
  if (manhole_x_) {
    manhole_id_ = next_id++;
    surfaces_.push_back(make_surface(manhole_id_, "manhole", "", "", -Eigen::Vector3d::UnitX(),
                                     *manhole_x_));
  }
  if (end_x_) {
    end_id_ = next_id++;
    surfaces_.push_back(make_surface(end_id_, "end", "", "", -Eigen::Vector3d::UnitX(), *end_x_));
  }

  // Rivet dome = spherical cap of base radius a and height h: sphere radius (a^2+h^2)/(2h),
  // centre (R - h) behind the wall surface.
  const double a = config.rivet_radius_m, h = config.rivet_height_m;
  if (h > 0.0) {
    sphere_radius_ = (a * a + h * h) / (2.0 * h);
    sphere_depth_ = sphere_radius_ - h;
  }

  // Rust patches: fixed for the tunnel (independent of the frame), from the seed.
  SimRandom rng(config.seed, kStreamGeometry, 0);
  texture_key_ = (static_cast<std::uint64_t>(rng.bits()) << 32) | rng.bits();
  double far_x = 6.0;
  if (manhole_x_) far_x = std::max(far_x, *manhole_x_ + 1.0);
  if (end_x_) far_x = std::min(std::max(far_x, 1.0), *end_x_ + 0.5);
  rust_.resize(4);
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < config.rust_patches_per_wall; ++k) {
      RustPatch p;
      p.x = rng.uniform(-0.5, far_x);
      p.s = rng.uniform(walls_[i].s_min, walls_[i].s_max);
      p.rx = rng.uniform(0.08, 0.35);
      p.rs = rng.uniform(0.05, 0.20);
      rust_[i].push_back(p);
    }
  }
}

RayHit TunnelGeometry::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& r) const {
  RayHit best;
  for (const Wall& w : walls_) cast_wall(w, o, r, best);
  const double H = config_.height_m;
  if (manhole_x_ && r.x() > 1e-12) {
    const double t = (*manhole_x_ - o.x()) / r.x();
    if (t > 0.0 && t < best.t) {
      const Eigen::Vector3d p = o + t * r;
      const double ey = p.y() / (0.5 * config_.manhole_width_m);
      const double ez = (p.z() - 0.5 * H) / (0.5 * config_.manhole_height_m);
      if (ey * ey + ez * ez >= 1.0) {  // outside the opening: the plate
        best = RayHit{};
        best.t = t;
        best.surface_id = manhole_id_;
        best.point = p;
        best.normal = -Eigen::Vector3d::UnitX();
        best.plane_offset = *manhole_x_;
      }
    }
  }
  if (end_x_ && r.x() > 1e-12) {
    const double t = (*end_x_ - o.x()) / r.x();
    if (t > 0.0 && t < best.t) {
      best = RayHit{};
      best.t = t;
      best.surface_id = end_id_;
      best.point = o + t * r;
      best.normal = -Eigen::Vector3d::UnitX();
      best.plane_offset = *end_x_;
    }
  }
  return best;
}

void TunnelGeometry::cast_wall(const Wall& w, const Eigen::Vector3d& o, const Eigen::Vector3d& r,
                               RayHit& best) const {
  const double dn = w.n.dot(r);
  if (dn >= -1e-12) return;  // moving away from (or along) this wall
  const double h0 = w.n.dot(o) + w.d_outer;  // height of the origin above the outer plane
  const double so = w.es.dot(o), sr = w.es.dot(r);
  auto take = [&](double t, int id, const Eigen::Vector3d& n, double offset) {
    best = RayHit{};
    best.t = t;
    best.surface_id = id;
    best.wall = static_cast<int>(&w - walls_.data());
    best.point = o + t * r;
    best.normal = n;
    best.plane_offset = offset;
  };
  // Middle plate (inner plane, height = thickness).
  const double t_in = (w.thickness - h0) / dn;
  if (t_in > 0.0 && t_in < best.t) {
    const double s = so + t_in * sr;
    if (s > w.s_mid_lo && s < w.s_mid_hi) take(t_in, w.middle_id, w.n, w.d_outer - w.thickness);
  }
  // Edge bands (outer plane).
  const double t_out = -h0 / dn;
  if (t_out > 0.0 && t_out < best.t) {
    const double s = so + t_out * sr;
    if (s >= w.s_min - 1e-9 && s <= w.s_mid_lo) take(t_out, w.edge_lo_id, w.n, w.d_outer);
    else if (s >= w.s_mid_hi && s <= w.s_max + 1e-9) take(t_out, w.edge_hi_id, w.n, w.d_outer);
  }
  // Step faces between the plate and the bands, seen from the band side.
  if (w.thickness > 0.0 && std::abs(sr) > 1e-12) {
    const bool lo = sr > 0.0;
    const double s0 = lo ? w.s_mid_lo : w.s_mid_hi;
    const double t = (s0 - so) / sr;
    if (t > 0.0 && t < best.t) {
      const double h = h0 + t * dn;
      if (h >= 0.0 && h <= w.thickness) {
        if (lo) take(t, w.step_lo_id, -w.es, w.s_mid_lo);
        else take(t, w.step_hi_id, w.es, -w.s_mid_hi);
      }
    }
  }
  if (!w.rivet_row_s.empty()) cast_rivets(w, o, r, h0, dn, best);
}

void TunnelGeometry::cast_rivets(const Wall& w, const Eigen::Vector3d& o, const Eigen::Vector3d& r,
                                 double h0, double dn, RayHit& best) const {
  // Only rivets under the stretch of ray that is lower than a dome can be hit.
  const double t_top = std::max(0.0, (config_.rivet_height_m - h0) / dn);
  const double t_bottom = -h0 / dn;
  if (t_bottom <= 0.0 || t_top >= best.t) return;
  const double a = config_.rivet_radius_m, pitch = config_.rivet_pitch_m;
  const double R = sphere_radius_;
  const double s1 = w.es.dot(o + t_top * r), s2 = w.es.dot(o + t_bottom * r);
  const double x1 = o.x() + t_top * r.x(), x2 = o.x() + t_bottom * r.x();
  const double s_lo = std::min(s1, s2) - a, s_hi = std::max(s1, s2) + a;
  const double x_lo = std::min(x1, x2) - a, x_hi = std::max(x1, x2) + a;
  for (std::size_t row = 0; row < w.rivet_row_s.size(); ++row) {
    const double sr = w.rivet_row_s[row];
    if (sr < s_lo || sr > s_hi) continue;
    const double phase = w.rivet_row_phase[row];
    const long k0 = static_cast<long>(std::ceil((x_lo - phase) / pitch));
    const long k1 = static_cast<long>(std::floor((x_hi - phase) / pitch));
    for (long k = k0; k <= k1; ++k) {
      const double xk = phase + k * pitch;
      const Eigen::Vector3d base = xk * Eigen::Vector3d::UnitX() + sr * w.es - w.d_outer * w.n;
      const Eigen::Vector3d c = base - sphere_depth_ * w.n;
      const Eigen::Vector3d oc = o - c;
      const double b = oc.dot(r);
      const double disc = b * b - (oc.squaredNorm() - R * R);
      if (disc < 0.0) continue;
      const double t = -b - std::sqrt(disc);
      if (t <= 0.0 || t >= best.t) continue;
      const Eigen::Vector3d p = o + t * r;
      if (w.n.dot(p) + w.d_outer < 0.0) continue;  // below the plate surface: not the dome
      best = RayHit{};
      best.t = t;
      best.surface_id = kSimRivetId;
      best.wall = static_cast<int>(&w - walls_.data());
      best.point = p;
      best.normal = (p - c) / R;
      best.rivet = true;
      best.sphere_center = c;
      best.sphere_radius = R;
    }
  }
}

bool TunnelGeometry::on_rust(const RayHit& hit) const {
  if (hit.wall < 0) return false;
  const double x = hit.point.x(), s = walls_[hit.wall].es.dot(hit.point);
  for (const RustPatch& p : rust_[hit.wall]) {
    const double dx = (x - p.x) / p.rx, ds = (s - p.s) / p.rs;
    if (dx * dx + ds * ds < 1.0) return true;
  }
  return false;
}

double TunnelGeometry::value_noise(int wall, double x, double s, double cell) const {
  const double fx = x / cell, fs = s / cell;
  const double ix = std::floor(fx), is = std::floor(fs);
  const double ax = fx - ix, as = fs - is;
  auto corner = [&](double cx, double cs) {
    const std::uint64_t key = texture_key_ ^ (static_cast<std::uint64_t>(wall) << 56) ^
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(cx)) *
                               0x9E3779B185EBCA87ull) ^
                              (static_cast<std::uint64_t>(static_cast<std::int64_t>(cs)) *
                               0xC2B2AE3D27D4EB4Full);
    return (splitmix64(key) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
  };
  const double v00 = corner(ix, is), v10 = corner(ix + 1, is);
  const double v01 = corner(ix, is + 1), v11 = corner(ix + 1, is + 1);
  return (v00 * (1 - ax) + v10 * ax) * (1 - as) + (v01 * (1 - ax) + v11 * ax) * as;
}

double TunnelGeometry::rust_relief_m(const RayHit& hit) const {
  if (config_.rust_roughness_m <= 0.0 || !on_rust(hit)) return 0.0;
  const double s = walls_[hit.wall].es.dot(hit.point);
  // Two octaves: pits of ~1 cm and fine grain of ~3 mm.
  const double v = 0.7 * value_noise(hit.wall, hit.point.x(), s, 0.010) +
                   0.3 * value_noise(hit.wall + 8, hit.point.x(), s, 0.003);
  return config_.rust_roughness_m * v;
}

double TunnelGeometry::texture(const RayHit& hit) const {
  if (hit.wall < 0) return 0.0;
  return value_noise(hit.wall + 16, hit.point.x(), walls_[hit.wall].es.dot(hit.point), 0.02);
}

}  // namespace tunnelmap::sim
