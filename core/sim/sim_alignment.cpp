#include "core/sim/sim_alignment.h"

#include <algorithm>
#include <cmath>

#include "core/sim/sim_sections.h"

namespace tunnelmap::sim {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kMaxCompartment = 4.0;  // longest chord between joints, metres
constexpr double kClothoidStep = 0.25;   // Simpson step along a transition curve, metres
}  // namespace

SimAlignment::SimAlignment(const SimConfig& c, std::vector<double> joints, double lo, double hi) {
  straight_ = !c.curved();
  if (straight_) {
    frames_ = {Eigen::Isometry3d::Identity()};
    inverse_ = frames_;
    return;
  }
  curvature_ = c.curve_radius_m == 0.0 ? 0.0 : 1.0 / c.curve_radius_m;
  transition_ = c.transition_m;
  transition_start_ = c.transition_start_m;
  gradient_ = c.gradient_pct / 100.0;
  vertical_curvature_ = c.vertical_radius_m == 0.0 ? 0.0 : 1.0 / c.vertical_radius_m;
  zc_ = 0.5 * SimSections(c).at(0.0).height_m;

  // Joint stations: the plates, station 0 and lo/hi, with more so no chord exceeds 4 m.
  joints.push_back(0.0);
  joints.push_back(lo);
  joints.push_back(hi);
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end(),
                           [](double a, double b) { return b - a < 1e-6; }),
               joints.end());
  std::vector<double> s;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (i > 0) {
      const double gap = joints[i] - joints[i - 1];
      const int n = static_cast<int>(std::ceil(gap / kMaxCompartment - 1e-9));
      for (int k = 1; k < n; ++k) s.push_back(joints[i - 1] + gap * k / n);
    }
    s.push_back(joints[i]);
  }
  // Alignment parameter of every joint: polyline lengths equal station differences.
  const std::size_t i0 = std::find(s.begin(), s.end(), 0.0) - s.begin();
  std::vector<double> h(s.size(), 0.0);
  for (std::size_t i = i0 + 1; i < s.size(); ++i) h[i] = chord_to(h[i - 1], s[i] - s[i - 1], 1.0);
  for (std::size_t i = i0; i-- > 0;) h[i] = chord_to(h[i + 1], s[i + 1] - s[i], -1.0);

  // Compartment frames: between joints i-1 and i; the first and last continue the next chord.
  const std::size_t m = s.size();
  const double cf = c.cross_fall_deg * kDeg;
  auto frame = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double station_a) {
    const Eigen::Vector3d x = (b - a).normalized();
    const Eigen::Vector3d y0 = Eigen::Vector3d::UnitZ().cross(x).normalized();
    const Eigen::Vector3d z0 = x.cross(y0);
    Eigen::Matrix3d R;
    R.col(0) = x;
    R.col(1) = std::cos(cf) * y0 + std::sin(cf) * z0;
    R.col(2) = -std::sin(cf) * y0 + std::cos(cf) * z0;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = R;
    T.translation() = a - R * Eigen::Vector3d(station_a, 0.0, zc_);
    return T;
  };
  std::vector<Eigen::Vector3d> P(m);
  for (std::size_t i = 0; i < m; ++i) P[i] = curve(h[i]);
  frames_.push_back(frame(curve(chord_to(h[0], kMaxCompartment, -1.0)), P[0], s[0] - kMaxCompartment));
  for (std::size_t i = 1; i < m; ++i) frames_.push_back(frame(P[i - 1], P[i], s[i - 1]));
  frames_.push_back(frame(P[m - 1], curve(chord_to(h[m - 1], kMaxCompartment, 1.0)), s[m - 1]));
  for (const Eigen::Isometry3d& T : frames_) inverse_.push_back(T.inverse());
  for (std::size_t i = 0; i < m; ++i) {
    SimJoint j;
    j.station = s[i];
    j.point = P[i];
    const Eigen::Matrix3d &A = frames_[i].linear(), &B = frames_[i + 1].linear();
    j.normal = (A.col(0) + B.col(0)).normalized();
    const Eigen::Vector3d up = A.col(2) + B.col(2);
    j.up = (up - up.dot(j.normal) * j.normal).normalized();
    j.left = j.up.cross(j.normal);
    joints_.push_back(j);
  }
}

double SimAlignment::heading(double h) const {
  if (transition_ <= 0.0) return curvature_ * h;
  const double u = std::clamp(h - transition_start_, 0.0, transition_);
  return curvature_ * (0.5 * u * u / transition_ + std::max(0.0, h - transition_start_ - transition_));
}

Eigen::Vector2d SimAlignment::plan(double h) const {
  // Straight, then the clothoid (integrated numerically: no closed form), then the arc.
  auto arc = [&](const Eigen::Vector2d& from, double h0, double length) -> Eigen::Vector2d {
    const double t0 = heading(h0), k = curvature_;
    if (std::abs(k * length) < 1e-12) return from + length * Eigen::Vector2d(std::cos(t0), std::sin(t0));
    return from + Eigen::Vector2d(std::sin(t0 + k * length) - std::sin(t0), std::cos(t0) - std::cos(t0 + k * length)) / k;
  };
  if (transition_ <= 0.0) return arc(Eigen::Vector2d::Zero(), 0.0, h);
  const double h0 = transition_start_, h1 = transition_start_ + transition_;
  if (h <= h0) return {h, 0.0};
  const double u = std::min(h, h1) - h0;
  const int n = 2 * std::max(1, static_cast<int>(std::ceil(u / kClothoidStep)));  // Simpson: even
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i <= n; ++i) {
    const double t = heading(h0 + u * i / n);
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * Eigen::Vector2d(std::cos(t), std::sin(t));
  }
  const Eigen::Vector2d end = Eigen::Vector2d(h0, 0.0) + sum * (u / n / 3.0);
  return h <= h1 ? end : arc(end, h1, h - h1);
}

Eigen::Vector3d SimAlignment::curve(double h) const {
  const Eigen::Vector2d p = plan(h);
  return {p.x(), p.y(), zc_ + gradient_ * h + 0.5 * vertical_curvature_ * h * h};
}

Eigen::Vector3d SimAlignment::curve_dir(double h) const {
  const double t = heading(h);
  return {std::cos(t), std::sin(t), gradient_ + vertical_curvature_ * h};
}

double SimAlignment::chord_to(double h_a, double length, double sign) const {
  // Newton on |curve(h) - curve(h_a)| = length, from the straight-line guess.
  const Eigen::Vector3d a = curve(h_a);
  const double slope = gradient_ + vertical_curvature_ * h_a;
  double h = h_a + sign * length / std::sqrt(1.0 + slope * slope);
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector3d d = curve(h) - a;
    const double f = d.norm() - length;
    const double df = sign * d.dot(curve_dir(h)) / std::max(d.norm(), 1e-12);
    if (std::abs(f) < 1e-13 || df == 0.0) break;
    h -= sign * f / df;
  }
  return h;
}

int SimAlignment::compartment_at_station(double s) const {
  return static_cast<int>(std::upper_bound(joints_.begin(), joints_.end(), s,
                                           [](double v, const SimJoint& j) { return v < j.station; }) -
                          joints_.begin());
}

int SimAlignment::compartment_containing(const Eigen::Vector3d& p) const {
  // The joints behind p are a prefix (the mitre planes do not cross inside the girder).
  return static_cast<int>(std::partition_point(joints_.begin(), joints_.end(),
                                               [&](const SimJoint& j) {
                                                 return j.normal.dot(p - j.point) >= 0.0;
                                               }) -
                          joints_.begin());
}

Eigen::Vector3d SimAlignment::to_world(const Eigen::Vector3d& local) const {
  if (straight_) return local;
  return frames_[compartment_at_station(local.x())] * local;
}

Eigen::Isometry3d SimAlignment::to_world(const Eigen::Isometry3d& local) const {
  if (straight_) return local;
  return frames_[compartment_at_station(local.translation().x())] * local;
}

Eigen::Vector3d SimAlignment::axis_at(double s) const {
  if (straight_) return Eigen::Vector3d::UnitX();
  return frames_[compartment_at_station(s)].linear().col(0);
}

}  // namespace tunnelmap::sim
