#include "core/sim/sim_girder.h"

#include <algorithm>
#include <cmath>

namespace tunnelmap::sim {

std::optional<double> manhole_plate_x(const SimConfig& c) {
  // The plate is fixed in the world; cameras stand `distance` in front of it.
  if (c.distance_to_manhole_m) return *c.distance_to_manhole_m;
  if (c.manhole_distances_m.empty()) return std::nullopt;
  return *std::max_element(c.manhole_distances_m.begin(), c.manhole_distances_m.end());
}

std::vector<double> diaphragm_stations(const SimConfig& c) {
  std::vector<double> x = c.diaphragm_x_m;
  if (c.diaphragm_spacing_m > 0.0 && c.girder_length_m) {
    const double S = c.diaphragm_spacing_m, L = *c.girder_length_m;
    // Diaphragms stand evenly spaced from the start; a last bay shorter than half the spacing
    // is not built (the end bay takes it), so no diaphragm stands a hand's width before the end.
    for (int k = 1; k * S <= L - 0.5 * S + 1e-9; ++k) x.push_back(k * S);
  }
  if (const std::optional<double> manhole = manhole_plate_x(c))
    x.erase(std::remove_if(x.begin(), x.end(), [&](double d) { return std::abs(d - *manhole) < kMinPlateGapM; }),
            x.end());
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end(), [](double a, double b) { return b - a < 1e-3; }), x.end());
  return x;
}

bool in_opening(const SimConfig& c, double dy, double dz) {
  if (c.manhole_shape == "rounded_rectangle") {
    const double hw = 0.5 * c.manhole_width_m, hh = 0.5 * c.manhole_height_m;
    const double ay = std::abs(dy), az = std::abs(dz);
    if (ay >= hw || az >= hh) return false;
    const double r = c.manhole_corner_radius_m;
    const double qy = ay - (hw - r), qz = az - (hh - r);
    return qy <= 0.0 || qz <= 0.0 || qy * qy + qz * qz < r * r;
  }
  const double ey = dy / (0.5 * c.manhole_width_m);
  const double ez = dz / (0.5 * c.manhole_height_m);
  return ey * ey + ez * ez < 1.0;
}

double opening_weight(double d) {
  if (d <= 0.5) return 1.0;
  if (d >= 1.5) return 0.0;
  const double u = 1.5 - d;  // 1 at 0.5 m, 0 at 1.5 m
  return u * u * (3.0 - 2.0 * u);
}

std::vector<bool> look_back_stops(const std::vector<double>& stop_x, const std::vector<double>& plates_x) {
  std::vector<bool> back(stop_x.size(), false);
  if (stop_x.empty()) return back;
  for (std::size_t k = 0; k < plates_x.size(); ++k) {
    const double from = plates_x[k];
    const bool last = k + 1 == plates_x.size();  // ends at the last stop, which may look back
    const double to = last ? stop_x.back() : plates_x[k + 1];
    if (to - from < kMinLookBackRoomM) continue;
    const double middle = 0.5 * (from + to);
    std::size_t nearest = stop_x.size();
    for (std::size_t g = 0; g < stop_x.size(); ++g)
      if (stop_x[g] > from && (stop_x[g] < to || (last && stop_x[g] == to)) &&
          (nearest == stop_x.size() || std::abs(stop_x[g] - middle) < std::abs(stop_x[nearest] - middle)))
        nearest = g;
    if (nearest < stop_x.size()) back[nearest] = true;
  }
  return back;
}

}  // namespace tunnelmap::sim
