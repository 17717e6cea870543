#include "core/evaluation/girder_family.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace tunnelmap {

namespace {

class Draw {
 public:
  explicit Draw(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  unsigned seed() { return static_cast<unsigned>(rng_()); }

 private:
  std::mt19937 rng_;
};

// 2-3 sections whose widths and heights step by 15-40 mm, over the girder's length.
void draw_sections(Draw& d, double length, double width, double height, SimConfig& c) {
  const int n = d.integer(2, 3);
  double w = width, h = height;
  for (int k = 0; k < n; ++k) {
    SimSection s;
    s.length_m = length / n;
    s.width_m = w;
    s.height_m = h;
    c.sections.push_back(s);
    const double sign = d.chance(0.5) ? 1.0 : -1.0;
    if (d.chance(0.5)) w += sign * d.uniform(0.015, 0.04);
    else h += sign * d.uniform(0.015, 0.04);
  }
  c.sections_start_x_m = 0.0;
}

void draw_manhole(Draw& d, double width, double height, SimConfig& c) {
  c.manhole_shape = d.chance(0.5) ? "ellipse" : "rounded_rectangle";
  c.manhole_width_m = std::min(d.uniform(0.40, 0.60), width - 0.2);
  c.manhole_height_m = std::min(d.uniform(0.60, 0.85), height - 0.3);
  c.manhole_corner_radius_m = d.uniform(0.05, 0.4) * std::min(c.manhole_width_m, c.manhole_height_m);
  c.manhole_centre_z_rel = d.uniform(0.42, 0.55);
}

// A transition curve and a vertical curve for a curved girder (GirderRanges): the straight
// ends 10-60 % along the girder, and the gradient stays within the range over its length.
void draw_alignment_changes(Draw& d, const GirderRanges& r, double length, SimConfig& c) {
  if (d.chance(r.transition_fraction)) {
    c.transition_start_m = d.uniform(0.1, 0.6) * length;
    c.transition_m = d.uniform(r.min_transition_m, r.max_transition_m);
  }
  if (d.chance(r.vertical_curve_fraction)) {
    const double radius = d.uniform(r.min_vertical_radius_m, r.max_vertical_radius_m);
    const double change_pct = 100.0 * length / radius;
    const double g0 = std::clamp(c.gradient_pct, -r.max_gradient_pct, r.max_gradient_pct);
    // Rise or fall, whichever keeps the gradient in range (both, when the range allows).
    const bool can_sag = g0 + change_pct <= r.max_gradient_pct;
    const bool can_crest = g0 - change_pct >= -r.max_gradient_pct;
    const bool sag = can_sag && (!can_crest || d.chance(0.5));
    if (can_sag || can_crest) c.vertical_radius_m = sag ? radius : -radius;
  }
}

}  // namespace

std::vector<GirderDraw> draw_girders(int count, unsigned seed, const GirderRanges& r) {
  Draw d(seed);
  Draw alignment_changes(seed ^ 0x5bd1e995u);
  Draw look_backs(seed ^ 0x27d4eb2fu);
  std::vector<GirderDraw> out;
  for (int i = 0; i < count; ++i) {
    GirderDraw g;
    g.index = i;
    SimConfig& c = g.config;
    c = SimConfig::from_preset(d.chance(0.5) ? "lab" : "field");
    c.seed = d.seed();
    const double length = d.uniform(r.min_length_m, r.max_length_m);
    const double width = d.uniform(r.min_width_m, r.max_width_m);
    const double height = d.uniform(r.min_height_m, r.max_height_m);
    c.width_m = width;
    c.height_m = height;
    c.girder_length_m = length;
    c.diaphragm_spacing_m = d.uniform(r.min_spacing_m, r.max_spacing_m);
    g.constant_section = !d.chance(r.sectioned_fraction);
    if (!g.constant_section) draw_sections(d, length, width, height, c);
    draw_manhole(d, width, height, c);
    const bool curved = d.chance(r.curved_fraction);
    if (curved) {
      c.curve_radius_m = (d.chance(0.5) ? 1 : -1) * d.uniform(r.min_radius_m, r.max_radius_m);
      c.gradient_pct = d.uniform(-r.max_gradient_pct, r.max_gradient_pct);
      c.cross_fall_deg = d.uniform(-r.max_cross_fall_deg, r.max_cross_fall_deg);
      draw_alignment_changes(alignment_changes, r, length, c);
    }
    c.noise_model = d.chance(0.7) ? "structured_light" : "tof";
    c.noise_scale = d.uniform(0.7, 1.3);
    g.drifted = d.chance(r.drifted_fraction);
    c.imu_gravity_deg = r.imu_gravity_deg;
    if (g.drifted) {
      c.drift_translation_mm_per_sqrt_m = r.drift_translation_mm_per_sqrt_m;
      c.drift_rotation_deg_per_sqrt_m = r.drift_rotation_deg_per_sqrt_m;
    }
    const double stop = d.uniform(r.min_stop_spacing_m, r.max_stop_spacing_m);
    SimWalk walk;
    walk.start_x_m = 0.4;
    walk.end_x_m = length - 1.0;
    walk.stops = std::max(2, static_cast<int>(std::lround((walk.end_x_m - walk.start_x_m) / stop)) + 1);
    walk.pose = {d.uniform(-0.1, 0.1), d.uniform(0.4, 0.6), 0.0, d.uniform(-4, 4), d.uniform(-4, 4)};
    walk.through_openings = true;
    walk.look_back = look_backs.chance(r.look_back_fraction);
    c.walk = walk;
    c.frames = walk.stops * r.frames_per_stop;
    std::string alignment;
    if (curved) {
      alignment = "R " + std::to_string(std::lround(c.curve_radius_m)) + " m, ";
      if (c.transition_m > 0.0)
        alignment += "straight to " + std::to_string(std::lround(c.transition_start_m)) + " m, transition " +
                     std::to_string(std::lround(c.transition_m)) + " m, ";
      if (c.vertical_radius_m != 0.0)
        alignment += "vertical R " + std::to_string(std::lround(c.vertical_radius_m)) + " m, ";
    }
    char buf[300];
    std::snprintf(buf, sizeof buf, "%.1f m, %.3f x %.3f m%s, plates every %.2f m, %s %.2f x %.2f m, %s%s",
                  length, width, height, g.constant_section ? "" : " (sections)",
                  c.diaphragm_spacing_m, c.manhole_shape.c_str(), c.manhole_width_m,
                  c.manhole_height_m, alignment.c_str(),
                  g.drifted ? "drift" : "exact poses");
    g.summary = buf;
    if (walk.look_back) g.summary += ", looks back";
    if (c.imu_gravity_deg > 0.0) g.summary += ", IMU";
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace tunnelmap
