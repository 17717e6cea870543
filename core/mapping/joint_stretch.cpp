#include "core/mapping/joint_stretch.h"

#include <algorithm>
#include <cmath>

#include "core/util/median.h"

namespace tunnelmap {

namespace {

// A wall tells the side of a joint when it moves by this share of the section's step at least:
// one wall carries a step alone (a roof that rises). A wall's position is measured from the
// centre line, whose fit near a plate errs by a few millimetres sideways (3 mm on girder 10 of
// seed 2, a 335 m curve), as much as each wall of a centred 20 mm change moves.
constexpr double kWallShareOfStep = 0.75;

// Stations next to the stretch give a wall's position on each side: the centre line, from
// which the walls are measured, wanders by millimetres over a section's length.
constexpr int kNearStations = 5;

// The median of `wall` over up to kNearStations measured stations from `from` towards `to`.
double wall_near(const std::vector<std::array<double, 4>>& walls, int wall, int from, int to) {
  std::vector<double> v;
  const int dir = to >= from ? 1 : -1;
  for (int k = from; static_cast<int>(v.size()) < kNearStations && (k - to) * dir <= 0; k += dir) {
    if (k < 0 || k >= static_cast<int>(walls.size())) continue;
    const double x = walls[static_cast<std::size_t>(k)][static_cast<std::size_t>(wall)];
    if (!std::isnan(x)) v.push_back(x);
  }
  return median_of_measured(v);
}

// Per station: -1 nearer `a`'s walls, +1 nearer `b`'s, 0 when no wall that carries the step
// tells (unseen, or the two disagree).
class WallSide {
 public:
  WallSide(const SectionRun& a, const SectionRun& b, const JointStretch& s,
           const std::vector<std::array<double, 4>>& wall_m)
      : walls_(wall_m), dim_(stepping_dimension(a, b)) {
    const double step = std::abs(dim_ == 0 ? b.width_m - a.width_m : b.height_m - a.height_m);
    for (int i = 0; i < 2; ++i) {
      ref_a_[i] = wall_near(walls_, 2 * dim_ + i, s.last_a, a.first);
      ref_b_[i] = wall_near(walls_, 2 * dim_ + i, s.first_b, b.last);
      carries_[i] = std::abs(ref_b_[i] - ref_a_[i]) > kWallShareOfStep * step;
    }
  }
  int at(int k) const {
    int vote = 0;
    for (int i = 0; i < 2; ++i) {
      const double x = walls_[static_cast<std::size_t>(k)][static_cast<std::size_t>(2 * dim_ + i)];
      if (!carries_[i] || std::isnan(x)) continue;
      const int v = std::abs(x - ref_a_[i]) < std::abs(x - ref_b_[i]) ? -1 : 1;
      if (vote != 0 && v != vote) return 0;
      vote = v;
    }
    return vote;
  }

 private:
  const std::vector<std::array<double, 4>>& walls_;
  int dim_;
  double ref_a_[2], ref_b_[2];
  bool carries_[2];
};

}  // namespace

int stepping_dimension(const SectionRun& a, const SectionRun& b) {
  const double dw = std::abs(b.width_m - a.width_m), dh = std::abs(b.height_m - a.height_m);
  return !(dh > dw) ? 0 : 1;
}

JointStretch stretch_between(const SectionRun& a, const SectionRun& b, const std::vector<double>& width_m,
                             const std::vector<double>& height_m) {
  const int dim = stepping_dimension(a, b);
  const std::vector<double>& size = dim == 0 ? width_m : height_m;
  const double size_a = dim == 0 ? a.width_m : a.height_m, size_b = dim == 0 ? b.width_m : b.height_m;
  const auto at = [&](int k) { return size[static_cast<std::size_t>(k)]; };
  const auto nearer_a = [&](int k) { return std::abs(at(k) - size_a) < std::abs(at(k) - size_b); };
  JointStretch s{a.first - 1, b.last + 1};
  for (int k = a.first; k <= a.last; ++k)
    if (!std::isnan(at(k)) && nearer_a(k)) s.last_a = k;
  for (int k = b.last; k >= b.first; --k)
    if (!std::isnan(at(k)) && !nearer_a(k)) s.first_b = k;
  return s;
}

// The first station inside nearer `b`'s walls ends the stretch; those nearer `a`'s before it
// start it later. Past a plate the roof ahead shows where it stepped while the floor beside
// the camera is out of view.
JointStretch narrowed_by_walls(const SectionRun& a, const SectionRun& b, JointStretch s,
                               const std::vector<std::array<double, 4>>& wall_m) {
  if (wall_m.empty()) return s;
  const WallSide side(a, b, s, wall_m);
  for (int k = s.last_a + 1; k < s.first_b && k < static_cast<int>(wall_m.size()); ++k) {
    const int v = side.at(k);
    if (v < 0) s.last_a = k;
    if (v > 0) {
      s.first_b = k;
      break;
    }
  }
  return s;
}

}  // namespace tunnelmap
