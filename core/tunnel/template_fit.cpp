#include "core/tunnel/template_fit.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "core/tunnel/normal_outliers.h"

namespace tunnelmap {

namespace {
// snprintf into `out`, reusing its buffer (a returned std::string would allocate every time).
void set_text(std::string& out, const char* f, double a, double b) {
  char buf[200];
  std::snprintf(buf, sizeof buf, f, a, b);
  out.assign(buf);
}
// A pair's weight: the sum of its seen walls' weights (1 each without weights).
double pair_weight(const double weights[4], const bool seen[4], int first) {
  double w = 0;
  for (int k = first; k < first + 2; ++k)
    if (seen[k]) w += weights ? weights[k] : 1.0;
  return w;
}
}  // namespace

TemplateFrame fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                                       const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                                       const Eigen::Vector3d& camera_forward,
                                       double max_pair_angle_deg) {
  TemplateFrame t;
  fit_rectangular_template(n_left, n_right, n_top, n_bottom, camera_forward, max_pair_angle_deg, t);
  return t;
}

void fit_rectangular_template(const Eigen::Vector3d& n_left, const Eigen::Vector3d& n_right,
                              const Eigen::Vector3d& n_top, const Eigen::Vector3d& n_bottom,
                              const Eigen::Vector3d& camera_forward, double max_pair_angle_deg,
                              TemplateFrame& t) {
  const Eigen::Vector3d means[4] = {n_left, n_right, n_top, n_bottom};
  const bool seen[4] = {true, true, true, true};
  // With every wall seen the rough directions are not used.
  fit_partial_template(means, seen, Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitY(),
                       camera_forward, max_pair_angle_deg, t);
}

void fit_partial_template(const Eigen::Vector3d means[4], const bool seen[4],
                          const Eigen::Vector3d& rough_right, const Eigen::Vector3d& rough_up,
                          const Eigen::Vector3d& camera_forward, double max_pair_angle_deg,
                          TemplateFrame& t, const double weights[4]) {
  {  // Default values in every field, but the reason keeps its buffer.
    TemplateFrame fresh;
    fresh.reason.swap(t.reason);
    fresh.reason.clear();
    t = std::move(fresh);
  }
  // A pair with both walls seen must be antiparallel.
  const auto parallel = [&](int a, int b, double& angle, const char* text) {
    if (!seen[a] || !seen[b]) return true;
    angle = angle_deg(means[a], -means[b]);
    if (angle <= max_pair_angle_deg) return true;
    t.status = TunnelStatus::NoParallelPair;
    set_text(t.reason, text, angle, max_pair_angle_deg);
    return false;
  };
  if (!parallel(0, 1, t.left_right_angle_deg,
                "left and right walls are %.1f deg from parallel (max %.1f)") ||
      !parallel(3, 2, t.top_bottom_angle_deg,
                "top and bottom walls are %.1f deg from parallel (max %.1f)"))
    return;
  // One direction per pair from the walls seen of it (inward normals: left faces right).
  const bool have_a = seen[0] || seen[1], have_b = seen[2] || seen[3];
  // A far sliver of floor (a few hundred points through a manhole, its normal 1 degree off)
  // must not tilt the axis as much as a roof of thousands of points does.
  const auto term = [&](int k) -> Eigen::Vector3d {
    return seen[k] ? Eigen::Vector3d((weights ? weights[k] : 1.0) * means[k]) : Eigen::Vector3d::Zero();
  };
  Eigen::Vector3d a = term(0) - term(1);
  Eigen::Vector3d b = term(3) - term(2);
  if (have_a) a.normalize();
  if (have_b) b.normalize();
  if (have_a && have_b) {
    t.pair_angle_deg = std::abs(angle_deg(a, b) - 90.0);
    if (t.pair_angle_deg > max_pair_angle_deg) {
      t.status = TunnelStatus::NotRectangular;
      set_text(t.reason, "wall pairs are %.1f deg from perpendicular (max %.1f)", t.pair_angle_deg,
               max_pair_angle_deg);
      return;
    }
    const double wa = pair_weight(weights, seen, 0), wb = pair_weight(weights, seen, 2);
    if (wa == wb) {  // the bisector-symmetric frame
      const Eigen::Vector3d s = (a + b).normalized();
      const Eigen::Vector3d d = (a - b).normalized();
      t.right = (s + d).normalized();
      t.up = (s - d).normalized();
    } else {
      // Each direction turns by its share of the misfit from perpendicular, in proportion to
      // the other pair's weight: a roof seen as a few rivet-studded strips must not turn "right",
      // which two walls of 50,000 points fix.
      const Eigen::Vector3d e2 = (b - a * a.dot(b)).normalized();
      const double phi = std::atan2(b.dot(e2), b.dot(a));
      const double turn_a = (0.5 * M_PI - phi) * wb / (wa + wb);
      const double angle_b = phi + (0.5 * M_PI - phi) * wa / (wa + wb);
      t.right = (std::cos(-turn_a) * a + std::sin(-turn_a) * e2).normalized();
      t.up = (std::cos(angle_b) * a + std::sin(angle_b) * e2).normalized();
    }
  } else if (have_a) {
    // The measured walls fix their own direction exactly; the other comes from "up".
    t.right = a;
    t.up = (rough_up - a * a.dot(rough_up)).normalized();
  } else {
    t.up = b;
    t.right = (rough_right - b * b.dot(rough_right)).normalized();
  }
  t.axis = t.up.cross(t.right);
  if (t.axis.dot(camera_forward) < 0) t.axis = -t.axis;
  t.ok = true;
}

}  // namespace tunnelmap
