#include "core/sim/tunnel_geometry.h"

#include <algorithm>
#include <cmath>

#include "core/sim/sim_random.h"
#include "core/sim/sim_sections.h"

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
  const SimSections layout(config);
  const std::vector<SimSpan>& spans = layout.spans();
  int next_id = 1;
  // Section k's zones and step faces take ids 20k+1 .. 20k+20, so without sections the wall
  // zones stay 1..12 in wall order.
  for (std::size_t k = 0; k < spans.size(); ++k)
    build_section(static_cast<int>(k), spans[k].from_x, spans[k].to_x, spans[k].width_m,
                  spans[k].height_m, next_id);
  if (!config.sections.empty()) {
    for (SimSurface& s : surfaces_) s.name = "section" + std::to_string(s.section) + "/" + s.name;
  }
  for (std::size_t k = 1; k < spans.size(); ++k) {
    // The joint's face looks into the section with the larger cross-section.
    const SimSpan &a = spans[k - 1], &b = spans[k];
    const double x = b.from_x;
    const bool faces_back = a.width_m * a.height_m >= b.width_m * b.height_m;
    joint_ids_.push_back(next_id);
    surfaces_.push_back(make_surface(next_id++, "joint", std::to_string(k - 1), "",
                                     Eigen::Vector3d(faces_back ? -1.0 : 1.0, 0.0, 0.0),
                                     faces_back ? x : -x));
  }
  if (manhole_x_) {
    manhole_ = Plate{*manhole_x_, 0.5 * layout.at(*manhole_x_).height_m, next_id++};
    surfaces_.push_back(make_surface(manhole_->id, "manhole", "", "", -Eigen::Vector3d::UnitX(),
                                     *manhole_x_));
  }
  for (std::size_t i = 0; i < config.diaphragm_x_m.size(); ++i) {
    const double x = config.diaphragm_x_m[i];
    diaphragms_.push_back(Plate{x, 0.5 * layout.at(x).height_m, next_id++});
    surfaces_.push_back(make_surface(diaphragms_.back().id, "diaphragm", std::to_string(i), "",
                                     -Eigen::Vector3d::UnitX(), x));
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
  make_rust();
}

void TunnelGeometry::build_section(int k, double from_x, double to_x, double W, double H,
                                   int& next_id) {
  const double e = config_.edge_band_m;
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
  Section sec;
  sec.from_x = from_x;
  sec.to_x = to_x;
  const std::size_t first_surface = surfaces_.size();
  for (int i = 0; i < 4; ++i) {
    const Spec& sp = specs[i];
    Wall w;
    w.index = i;
    w.n = sp.n;
    w.d_outer = sp.d_outer;
    w.es = sp.es;
    w.s_min = sp.s_min;
    w.s_max = sp.s_max;
    w.s_mid_lo = sp.s_min + e;
    w.s_mid_hi = sp.s_max - e;
    w.thickness = config_.plate_thickness_m[i];
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
    const int rows = config_.rivet_height_m > 0.0 ? config_.rivet_rows_per_band : 0;
    for (int r = 0; r < rows; ++r) {
      const double off = e * (r + 1) / (rows + 1);
      const double phase = (r % 2) * 0.5 * config_.rivet_pitch_m;
      w.rivet_row_s.push_back(w.s_min + off);
      w.rivet_row_phase.push_back(phase);
      w.rivet_row_s.push_back(w.s_max - off);
      w.rivet_row_phase.push_back(phase);
    }
    sec.walls.push_back(w);
    wall_es_[i] = w.es;
    rust_s_min_[i] = k == 0 ? w.s_min : std::min(rust_s_min_[i], w.s_min);
    rust_s_max_[i] = k == 0 ? w.s_max : std::max(rust_s_max_[i], w.s_max);
  }
  // Step faces after all zones so that zone ids stay 1..12 in wall order.
  for (int i = 0; i < 4; ++i) {
    Wall& w = sec.walls[i];
    w.step_lo_id = next_id++;
    w.step_hi_id = next_id++;
    surfaces_.push_back(make_surface(w.step_lo_id, specs[i].name, std::string("step_") + specs[i].lo,
                                     "step", -w.es, w.s_mid_lo));
    surfaces_.push_back(make_surface(w.step_hi_id, specs[i].name, std::string("step_") + specs[i].hi,
                                     "step", w.es, -w.s_mid_hi));
  }
  for (std::size_t i = first_surface; i < surfaces_.size(); ++i) surfaces_[i].section = k;
  sections_.push_back(std::move(sec));
}

void TunnelGeometry::make_rust() {
  // Rust patches: fixed for the tunnel (independent of the frame), from the seed, over the
  // stretch the cameras see (a walk's stations plus the view ahead).
  SimRandom rng(config_.seed, kStreamGeometry, 0);
  texture_key_ = (static_cast<std::uint64_t>(rng.bits()) << 32) | rng.bits();
  double near_x = -0.5, far_x = 6.0;
  if (config_.walk) {
    near_x = std::min(config_.walk->start_x_m, config_.walk->end_x_m) - 0.5;
    far_x = std::max(config_.walk->start_x_m, config_.walk->end_x_m) + 6.0;
  }
  if (manhole_x_) far_x = std::max(far_x, *manhole_x_ + 1.0);
  if (end_x_) far_x = std::min(std::max(far_x, 1.0), *end_x_ + 0.5);
  // The patch density of the constant tunnel (rust_patches_per_wall per 6.5 m) on long walks.
  const int patches =
      config_.rust_patches_per_wall *
      (config_.walk ? std::max(1, static_cast<int>(std::lround((far_x - near_x) / 6.5))) : 1);
  rust_.resize(4);
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < patches; ++k) {
      RustPatch p;
      p.x = rng.uniform(near_x, far_x);
      p.s = rng.uniform(rust_s_min_[i], rust_s_max_[i]);
      p.rx = rng.uniform(0.08, 0.35);
      p.rs = rng.uniform(0.05, 0.20);
      rust_[i].push_back(p);
    }
  }
}

bool TunnelGeometry::Section::open(const Eigen::Vector3d& p) const {
  for (const Wall& w : walls) {
    const double h = w.n.dot(p) + w.d_outer, s = w.es.dot(p);
    if (h <= 0.0) return false;
    if (s > w.s_mid_lo && s < w.s_mid_hi && h <= w.thickness) return false;
  }
  return true;
}

RayHit TunnelGeometry::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& r) const {
  RayHit best;
  cast_sections(o, r, best);
  if (manhole_) cast_plate(*manhole_, false, o, r, best);
  for (const Plate& d : diaphragms_) cast_plate(d, true, o, r, best);
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

void TunnelGeometry::cast_sections(const Eigen::Vector3d& o, const Eigen::Vector3d& r,
                                   RayHit& best) const {
  // Walk the sections in the ray's direction from the origin's, crossing joints until a hit is
  // nearer than the next joint or the crossing point is outside the next free cross-section.
  const int n = static_cast<int>(sections_.size());
  // The origin's section: the first whose end is beyond it (the last one has none).
  int k = static_cast<int>(std::upper_bound(sections_.begin(), sections_.end() - 1, o.x(),
                                            [](double x, const Section& s) { return x < s.to_x; }) -
                           sections_.begin());
  const int step = r.x() > 1e-12 ? 1 : r.x() < -1e-12 ? -1 : 0;
  for (;;) {
    const Section& sec = sections_[k];
    for (const Wall& w : sec.walls) cast_wall(sec, k, w, o, r, best);
    const int next = k + step;
    if (step == 0 || next < 0 || next >= n) return;
    const double xj = step > 0 ? sec.to_x : sec.from_x;
    const double t = (xj - o.x()) / r.x();
    if (t >= best.t) return;
    const Eigen::Vector3d p = o + t * r;
    if (!sections_[next].open(p)) {
      const int joint = step > 0 ? k : next;
      best = RayHit{};
      best.t = t;
      best.surface_id = joint_ids_[joint];
      best.point = p;
      best.normal = Eigen::Vector3d(step > 0 ? -1.0 : 1.0, 0.0, 0.0);
      best.plane_offset = step > 0 ? xj : -xj;
      return;
    }
    k = next;
  }
}

void TunnelGeometry::cast_plate(const Plate& plate, bool two_sided, const Eigen::Vector3d& o,
                                const Eigen::Vector3d& r, RayHit& best) const {
  const bool ahead = r.x() > 1e-12;
  if (!ahead && !(two_sided && r.x() < -1e-12)) return;
  const double t = (plate.x - o.x()) / r.x();
  if (t <= 0.0 || t >= best.t) return;
  const Eigen::Vector3d p = o + t * r;
  const double ey = p.y() / (0.5 * config_.manhole_width_m);
  const double ez = (p.z() - plate.centre_z) / (0.5 * config_.manhole_height_m);
  if (ey * ey + ez * ez < 1.0) return;  // through the opening
  best = RayHit{};
  best.t = t;
  best.surface_id = plate.id;
  best.point = p;
  best.normal = Eigen::Vector3d(ahead ? -1.0 : 1.0, 0.0, 0.0);
  best.plane_offset = ahead ? plate.x : -plate.x;
}

void TunnelGeometry::cast_wall(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                               const Eigen::Vector3d& r, RayHit& best) const {
  const double dn = w.n.dot(r);
  if (dn >= -1e-12) return;  // moving away from (or along) this wall
  const double h0 = w.n.dot(o) + w.d_outer;  // height of the origin above the outer plane
  const double so = w.es.dot(o), sr = w.es.dot(r);
  auto take = [&](double t, int id, const Eigen::Vector3d& n, double offset) {
    if (!sec.contains_x(o.x() + t * r.x())) return;  // beyond this section's joints
    best = RayHit{};
    best.t = t;
    best.surface_id = id;
    best.wall = w.index;
    best.section = k;
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
  if (!w.rivet_row_s.empty()) cast_rivets(sec, k, w, o, r, h0, dn, best);
}

void TunnelGeometry::cast_rivets(const Section& sec, int k, const Wall& w,
                                 const Eigen::Vector3d& o, const Eigen::Vector3d& r, double h0,
                                 double dn, RayHit& best) const {
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
    for (long i = k0; i <= k1; ++i) {
      const double xk = phase + i * pitch;
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
      if (!sec.contains_x(p.x())) continue;          // cut at the section's joints
      best = RayHit{};
      best.t = t;
      best.surface_id = kSimRivetId;
      best.wall = w.index;
      best.section = k;
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
  const double x = hit.point.x(), s = wall_es_[hit.wall].dot(hit.point);
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
  const double s = wall_es_[hit.wall].dot(hit.point);
  // Two octaves: pits of ~1 cm and fine grain of ~3 mm.
  const double v = 0.7 * value_noise(hit.wall, hit.point.x(), s, 0.010) +
                   0.3 * value_noise(hit.wall + 8, hit.point.x(), s, 0.003);
  return config_.rust_roughness_m * v;
}

double TunnelGeometry::texture(const RayHit& hit) const {
  if (hit.wall < 0) return 0.0;
  return value_noise(hit.wall + 16, hit.point.x(), wall_es_[hit.wall].dot(hit.point), 0.02);
}

}  // namespace tunnelmap::sim
