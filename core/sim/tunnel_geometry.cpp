#include "core/sim/tunnel_geometry.h"

#include <algorithm>
#include <cmath>

#include "core/sim/sim_girder.h"
#include "core/sim/sim_random.h"
#include "core/sim/sim_sections.h"
#include "core/util/error.h"

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
  if (config.girder_length_m) start_x_ = 0.0;
  if (config.curved()) {
    make_chain(config, next_id);
  } else {
    if (manhole_x_) {
      const double cz = opening_centre_z(config, layout.at(*manhole_x_).height_m);
      plates_.push_back(Plate{*manhole_x_, cz, next_id++, false});
      surfaces_.push_back(make_surface(plates_.back().id, "manhole", "", "",
                                       -Eigen::Vector3d::UnitX(), *manhole_x_));
    }
    const std::vector<double> diaphragms = diaphragm_stations(config);
    for (std::size_t i = 0; i < diaphragms.size(); ++i) {
      const double x = diaphragms[i];
      plates_.push_back(Plate{x, opening_centre_z(config, layout.at(x).height_m), next_id++, true});
      surfaces_.push_back(make_surface(plates_.back().id, "diaphragm", std::to_string(i), "",
                                       -Eigen::Vector3d::UnitX(), x));
    }
    for (const Plate& p : plates_) {
      PlateInfo info{p.x, p.id, p.centre_z, !p.two_sided};
      info.centre_world = Eigen::Vector3d(p.x, 0.0, p.centre_z);
      info.centreline_world = Eigen::Vector3d(p.x, 0.0, 0.5 * layout.at(p.x).height_m);
      plate_info_.push_back(info);
    }
    // By station, for the culling in cast_plates (the manhole plate first at a shared x).
    std::stable_sort(plates_.begin(), plates_.end(),
                     [](const Plate& a, const Plate& b) { return a.x < b.x; });
    if (end_x_) {
      end_id_ = next_id++;
      surfaces_.push_back(make_surface(end_id_, "end", "", "", -Eigen::Vector3d::UnitX(), *end_x_));
    }
    if (start_x_) {
      start_id_ = next_id++;
      surfaces_.push_back(make_surface(start_id_, "end", "", "", Eigen::Vector3d::UnitX(), -*start_x_));
      surfaces_.back().name = "start";
    }
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
  // Stiffeners after the steps, so the ids above stay as they were without them.
  for (std::size_t j = 0; j < config_.stiffeners.size(); ++j) {
    const SimStiffener& st = config_.stiffeners[j];
    Wall& w = sec.walls[st.wall];
    const double half = 0.5 * config_.stiffener_thickness_m;
    const bool on_plate = st.position_m > w.s_mid_lo && st.position_m < w.s_mid_hi;
    Wall::Bar b{st.position_m - half, st.position_m + half,
                (on_plate ? w.thickness : 0.0) + config_.stiffener_height_m, 0, 0, 0};
    const std::string part = "stiffener" + std::to_string(j);
    b.top_id = next_id++;
    surfaces_.push_back(make_surface(b.top_id, specs[st.wall].name, part + "/top", "stiffener",
                                     w.n, w.d_outer - b.top));
    b.lo_id = next_id++;
    surfaces_.push_back(make_surface(b.lo_id, specs[st.wall].name, part + "/side_" + specs[st.wall].lo,
                                     "stiffener", -w.es, b.s_lo));
    b.hi_id = next_id++;
    surfaces_.push_back(make_surface(b.hi_id, specs[st.wall].name, part + "/side_" + specs[st.wall].hi,
                                     "stiffener", w.es, -b.s_hi));
    w.bars.push_back(b);
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
    std::sort(rust_[i].begin(), rust_[i].end(),
              [](const RustPatch& a, const RustPatch& b) { return a.x < b.x; });
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

void TunnelGeometry::make_chain(const SimConfig& c, int next_id) {
  // The straight geometry built so far is the local one; every compartment gets a copy of
  // its surfaces (ids + k * local_ids_, planes in the world), then the plates on the joints.
  local_ids_ = next_id - 1;
  const SimSections layout(c);
  const std::vector<double> diaphragms = diaphragm_stations(c);
  std::vector<double> stations = diaphragms;
  if (manhole_x_) stations.push_back(*manhole_x_);
  if (end_x_) stations.push_back(*end_x_);
  if (start_x_) stations.push_back(*start_x_);
  // The stretch the cameras see: their stations (as TunnelSimulator places them) +- range.
  double cam_lo = 0.0, cam_hi = 0.0;
  if (c.walk) {
    cam_lo = std::min(c.walk->start_x_m, c.walk->end_x_m);
    cam_hi = std::max(c.walk->start_x_m, c.walk->end_x_m);
  } else if (manhole_x_) {
    std::vector<double> d = c.manhole_distances_m;
    if (c.distance_to_manhole_m) d = {*c.distance_to_manhole_m};
    cam_lo = *manhole_x_ - *std::max_element(d.begin(), d.end());
    cam_hi = *manhole_x_ - *std::min_element(d.begin(), d.end());
  }
  double lo = cam_lo - c.max_depth_m - 1.0, hi = cam_hi + c.max_depth_m + 1.0;
  for (double x : stations) lo = std::min(lo, x), hi = std::max(hi, x);
  alignment_ = SimAlignment(c, stations, lo, hi);
  const int n = alignment_.compartment_count();
  const std::size_t id_count = static_cast<std::size_t>(n) * local_ids_ + stations.size();
  if (id_count >= kSimRivetId)
    throw ParameterError("simulator: the curved girder needs " + std::to_string(id_count) +
                         " surface ids (at most 65534): fewer sections or a shorter girder");
  const std::vector<SimSurface> local = std::move(surfaces_);
  surfaces_.clear();
  for (int k = 0; k < n; ++k) {
    const Eigen::Isometry3d& T = alignment_.world_from_local(k);
    for (SimSurface s : local) {
      s.id += k * local_ids_;
      s.name = "compartment" + std::to_string(k) + "/" + s.name;
      s.compartment = k;
      s.normal_world = T.linear() * s.normal_world;
      s.offset_world -= s.normal_world.dot(T.translation());
      surfaces_.push_back(s);
    }
  }
  int id = n * local_ids_ + 1;
  const std::vector<SimJoint>& joints = alignment_.joints();
  joint_plates_.assign(joints.size(), JointPlate{});
  auto joint_at = [&](double x) {
    std::size_t best = 0;
    for (std::size_t j = 0; j < joints.size(); ++j)
      if (std::abs(joints[j].station - x) < std::abs(joints[best].station - x)) best = j;
    return best;
  };
  auto add = [&](double x, const std::string& wall, const std::string& part, bool fwd, bool bwd,
                 bool full) {
    const std::size_t j = joint_at(x);
    const SimJoint& J = joints[j];
    JointPlate& p = joint_plates_[j];
    p.id = id++;
    p.forward = fwd;
    p.backward = bwd;
    p.full = full;
    const double cz = opening_centre_z(c, layout.at(x).height_m);
    p.centre = J.point + (cz - alignment_.reference_z()) * J.up;
    const Eigen::Vector3d n_face = bwd && !fwd ? J.normal : Eigen::Vector3d(-J.normal);
    surfaces_.push_back(make_surface(p.id, wall, part, "", n_face, -n_face.dot(J.point)));
    if (!full) {
      PlateInfo info{x, p.id, cz, !bwd};
      info.centre_world = p.centre;
      info.normal_world = J.normal;
      info.centreline_world = J.point + (0.5 * layout.at(x).height_m - alignment_.reference_z()) * J.up;
      plate_info_.push_back(info);
    }
  };
  if (manhole_x_) add(*manhole_x_, "manhole", "", true, false, false);
  for (std::size_t i = 0; i < diaphragms.size(); ++i)
    add(diaphragms[i], "diaphragm", std::to_string(i), true, true, false);
  if (end_x_) {
    end_id_ = id;
    add(*end_x_, "end", "", true, false, true);
  }
  if (start_x_) {
    start_id_ = id;
    add(*start_x_, "end", "", false, true, true);
    surfaces_.back().name = "start";
  }
}

std::vector<TunnelGeometry::PlateInfo> TunnelGeometry::plates() const {
  std::vector<PlateInfo> out = plate_info_;
  std::sort(out.begin(), out.end(), [](const PlateInfo& a, const PlateInfo& b) {
    return a.station < b.station;
  });
  return out;
}

RayHit TunnelGeometry::cast(const Eigen::Vector3d& o, const Eigen::Vector3d& r) const {
  if (!alignment_.straight()) return cast_chain(o, r);
  RayHit best;
  cast_sections(o, r, 0.0, best);
  cast_plates(o, r, best);
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
  if (start_x_ && r.x() < -1e-12) {
    const double t = (*start_x_ - o.x()) / r.x();
    if (t > 0.0 && t < best.t) {
      best = RayHit{};
      best.t = t;
      best.surface_id = start_id_;
      best.point = o + t * r;
      best.normal = Eigen::Vector3d::UnitX();
      best.plane_offset = -*start_x_;
    }
  }
  best.local_point = best.point;
  return best;
}

RayHit TunnelGeometry::cast_chain(const Eigen::Vector3d& o, const Eigen::Vector3d& r) const {
  // From the origin's compartment on, compartment by compartment: its walls between the
  // joint planes where the ray enters and leaves it, then the plate on the leaving joint.
  const std::vector<SimJoint>& J = alignment_.joints();
  const int n = alignment_.compartment_count();
  int k = alignment_.compartment_containing(o);
  double t0 = 0.0;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int guard = 0; guard <= n; ++guard) {
    double t1 = kInf;
    int exit = -1;
    bool forward = false;
    if (k < n - 1) {
      const double den = J[k].normal.dot(r);
      if (den > 1e-12) {
        const double t = J[k].normal.dot(J[k].point - o) / den;
        if (t >= t0 && t < t1) t1 = t, exit = k, forward = true;
      }
    }
    if (k > 0) {
      const double den = J[k - 1].normal.dot(r);
      if (den < -1e-12) {
        const double t = J[k - 1].normal.dot(J[k - 1].point - o) / den;
        if (t >= t0 && t < t1) t1 = t, exit = k - 1, forward = false;
      }
    }
    const Eigen::Isometry3d& L = alignment_.local_from_world(k);
    const Eigen::Vector3d ol = L * o, rl = L.linear() * r;
    RayHit best;
    best.t = t1;
    cast_sections(ol, rl, t0, best);
    if (best.hit()) {
      const Eigen::Isometry3d& W = alignment_.world_from_local(k);
      best.local_point = best.point;
      best.point = o + best.t * r;
      best.normal = W.linear() * best.normal;
      best.plane_offset -= best.normal.dot(W.translation());
      best.sphere_center = W * best.sphere_center;
      if (!best.rivet) best.surface_id += k * local_ids_;
      best.compartment = k;
      return best;
    }
    if (exit < 0) return RayHit{};
    const JointPlate& jp = joint_plates_[exit];
    if (jp.id != 0 && (forward ? jp.forward : jp.backward)) {
      const Eigen::Vector3d p = o + t1 * r;
      const Eigen::Vector3d d = p - jp.centre;
      if (jp.full || !in_opening(config_, d.dot(J[exit].left), d.dot(J[exit].up))) {
        RayHit hit;
        hit.t = t1;
        hit.surface_id = jp.id;
        hit.point = p;
        hit.local_point = L * p;
        hit.normal = forward ? Eigen::Vector3d(-J[exit].normal) : J[exit].normal;
        hit.plane_offset = -hit.normal.dot(J[exit].point);
        hit.compartment = k;
        return hit;
      }
    }
    k += forward ? 1 : -1;
    t0 = t1;
  }
  return RayHit{};
}

void TunnelGeometry::cast_sections(const Eigen::Vector3d& o, const Eigen::Vector3d& r,
                                   double t_min, RayHit& best) const {
  // Walk the sections in the ray's direction from the origin's, crossing joints until a hit is
  // nearer than the next joint or the crossing point is outside the next free cross-section.
  const int n = static_cast<int>(sections_.size());
  // The origin's section: the first whose end is beyond it (the last one has none).
  const double x0 = o.x() + t_min * r.x();
  int k = static_cast<int>(std::upper_bound(sections_.begin(), sections_.end() - 1, x0,
                                            [](double x, const Section& s) { return x < s.to_x; }) -
                           sections_.begin());
  const int step = r.x() > 1e-12 ? 1 : r.x() < -1e-12 ? -1 : 0;
  for (;;) {
    const Section& sec = sections_[k];
    for (const Wall& w : sec.walls) {
      cast_wall(sec, k, w, o, r, t_min, best);
      if (!w.bars.empty()) cast_bars(sec, k, w, o, r, t_min, best);
    }
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

void TunnelGeometry::cast_plates(const Eigen::Vector3d& o, const Eigen::Vector3d& r,
                                 RayHit& best) const {
  // Plates are sorted by x: only those ahead of the origin in the ray's direction, nearest
  // first, until one blocks the ray or lies beyond the best hit.
  auto hit = [&](const Plate& plate, bool ahead) {
    const double t = (plate.x - o.x()) / r.x();
    if (t <= 0.0) return false;
    if (t >= best.t) return true;  // this and every further plate are behind the best hit
    const Eigen::Vector3d p = o + t * r;
    if (in_opening(config_, p.y(), p.z() - plate.centre_z)) return false;  // through the opening
    best = RayHit{};
    best.t = t;
    best.surface_id = plate.id;
    best.point = p;
    best.normal = Eigen::Vector3d(ahead ? -1.0 : 1.0, 0.0, 0.0);
    best.plane_offset = ahead ? plate.x : -plate.x;
    return true;
  };
  const auto first_beyond = std::upper_bound(
      plates_.begin(), plates_.end(), o.x(), [](double x, const Plate& p) { return x < p.x; });
  if (r.x() > 1e-12) {
    for (auto it = first_beyond; it != plates_.end(); ++it)
      if (hit(*it, true)) return;
  } else if (r.x() < -1e-12) {
    for (auto it = first_beyond; it != plates_.begin();) {
      --it;
      if (it->two_sided && hit(*it, false)) return;
    }
  }
}

void TunnelGeometry::cast_wall(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                               const Eigen::Vector3d& r, double t_min, RayHit& best) const {
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
  if (t_in > t_min && t_in < best.t) {
    const double s = so + t_in * sr;
    if (s > w.s_mid_lo && s < w.s_mid_hi) take(t_in, w.middle_id, w.n, w.d_outer - w.thickness);
  }
  // Edge bands (outer plane).
  const double t_out = -h0 / dn;
  if (t_out > t_min && t_out < best.t) {
    const double s = so + t_out * sr;
    if (s >= w.s_min - 1e-9 && s <= w.s_mid_lo) take(t_out, w.edge_lo_id, w.n, w.d_outer);
    else if (s >= w.s_mid_hi && s <= w.s_max + 1e-9) take(t_out, w.edge_hi_id, w.n, w.d_outer);
  }
  // Step faces between the plate and the bands, seen from the band side.
  if (w.thickness > 0.0 && std::abs(sr) > 1e-12) {
    const bool lo = sr > 0.0;
    const double s0 = lo ? w.s_mid_lo : w.s_mid_hi;
    const double t = (s0 - so) / sr;
    if (t > t_min && t < best.t) {
      const double h = h0 + t * dn;
      if (h >= 0.0 && h <= w.thickness) {
        if (lo) take(t, w.step_lo_id, -w.es, w.s_mid_lo);
        else take(t, w.step_hi_id, w.es, -w.s_mid_hi);
      }
    }
  }
  if (!w.rivet_row_s.empty()) cast_rivets(sec, k, w, o, r, h0, dn, t_min, best);
}

void TunnelGeometry::cast_rivets(const Section& sec, int k, const Wall& w,
                                 const Eigen::Vector3d& o, const Eigen::Vector3d& r, double h0,
                                 double dn, double t_min, RayHit& best) const {
  // Only rivets under the stretch of ray that is lower than a dome can be hit.
  const double t_top = std::max(t_min, (config_.rivet_height_m - h0) / dn);
  const double t_bottom = -h0 / dn;
  if (t_bottom <= t_min || t_top >= best.t) return;
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
      if (t <= t_min || t >= best.t) continue;
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

void TunnelGeometry::cast_bars(const Section& sec, int k, const Wall& w, const Eigen::Vector3d& o,
                               const Eigen::Vector3d& r, double t_min, RayHit& best) const {
  // Each bar is a slab in (height above the outer plane, s across the wall): the ray enters
  // it through the top face or a side face, whichever slab it enters last.
  const double h0 = w.n.dot(o) + w.d_outer, dn = w.n.dot(r);
  const double so = w.es.dot(o), sr = w.es.dot(r);
  for (const Wall::Bar& b : w.bars) {
    double h_in = -std::numeric_limits<double>::infinity(), h_out = -h_in;
    if (std::abs(dn) > 1e-12) {
      const double ta = -h0 / dn, tb = (b.top - h0) / dn;
      h_in = std::min(ta, tb), h_out = std::max(ta, tb);
    } else if (h0 < 0.0 || h0 > b.top) {
      continue;
    }
    double s_in = -std::numeric_limits<double>::infinity(), s_out = -s_in;
    if (std::abs(sr) > 1e-12) {
      const double ta = (b.s_lo - so) / sr, tb = (b.s_hi - so) / sr;
      s_in = std::min(ta, tb), s_out = std::max(ta, tb);
    } else if (so < b.s_lo || so > b.s_hi) {
      continue;
    }
    const double t = std::max(h_in, s_in);
    if (t > std::min(h_out, s_out) || t <= t_min || t >= best.t) continue;
    if (!sec.contains_x(o.x() + t * r.x())) continue;
    best = RayHit{};
    best.t = t;
    best.wall = w.index;
    best.section = k;
    best.point = o + t * r;
    if (h_in >= s_in) {
      best.surface_id = b.top_id;
      best.normal = w.n;
      best.plane_offset = w.d_outer - b.top;
    } else if (sr > 0.0) {
      best.surface_id = b.lo_id;
      best.normal = -w.es;
      best.plane_offset = b.s_lo;
    } else {
      best.surface_id = b.hi_id;
      best.normal = w.es;
      best.plane_offset = -b.s_hi;
    }
  }
}

bool TunnelGeometry::on_rust(const RayHit& hit) const {
  if (hit.wall < 0) return false;
  const double x = hit.local_point.x(), s = wall_es_[hit.wall].dot(hit.local_point);
  const std::vector<RustPatch>& patches = rust_[hit.wall];  // sorted by x
  auto it = std::lower_bound(patches.begin(), patches.end(), x - kMaxRustRx,
                             [](const RustPatch& p, double v) { return p.x < v; });
  for (; it != patches.end() && it->x <= x + kMaxRustRx; ++it) {
    const double dx = (x - it->x) / it->rx, ds = (s - it->s) / it->rs;
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
  const Eigen::Vector3d& q = hit.local_point;
  const double s = wall_es_[hit.wall].dot(q);
  // Two octaves: pits of ~1 cm and fine grain of ~3 mm.
  const double v = 0.7 * value_noise(hit.wall, q.x(), s, 0.010) +
                   0.3 * value_noise(hit.wall + 8, q.x(), s, 0.003);
  return config_.rust_roughness_m * v;
}

double TunnelGeometry::texture(const RayHit& hit) const {
  if (hit.wall < 0) return 0.0;
  return value_noise(hit.wall + 16, hit.local_point.x(), wall_es_[hit.wall].dot(hit.local_point),
                     0.02);
}

}  // namespace tunnelmap::sim
