#include "core/mapping/compartment_bends.h"

#include <algorithm>
#include <array>
#include <map>

namespace tunnelmap {

namespace {

struct Compartment {
  std::vector<int> planes;
  double station_sum_m = 0.0;
  double station_m() const { return station_sum_m / static_cast<double>(planes.size()); }
};

// Per kind, per compartment (the number of plates before it): its whole bands.
std::map<int, std::map<int, Compartment>> compartments(const std::vector<WallBand>& bands,
                                                       const std::vector<double>& plates) {
  std::map<int, std::map<int, Compartment>> out;
  for (const WallBand& b : bands) {
    const auto next = std::upper_bound(plates.begin(), plates.end(), b.from_m);
    if (next != plates.end() && *next < b.to_m) continue;  // a plate inside the band
    if (next == plates.begin() || next == plates.end()) continue;  // open-ended
    Compartment& c = out[b.kind][static_cast<int>(next - plates.begin())];
    c.planes.push_back(b.plane);
    c.station_sum_m += 0.5 * (b.from_m + b.to_m);
  }
  return out;
}

// Lagrange weights of the quadratic through `at` (three stations) at station `s`.
std::array<double, 3> quadratic_weights(const std::array<double, 3>& at, double s) {
  std::array<double, 3> w{};
  for (int i = 0; i < 3; ++i) {
    w[i] = 1.0;
    for (int j = 0; j < 3; ++j)
      if (j != i) w[i] *= (s - at[j]) / (at[i] - at[j]);
  }
  return w;
}

}  // namespace

std::vector<PlaneBend> compartment_bends(const std::vector<WallBand>& bands, std::vector<double> plate_stations_m,
                                         double sigma_rad) {
  std::sort(plate_stations_m.begin(), plate_stations_m.end());
  std::vector<PlaneBend> out;
  for (const auto& [kind, of_kind] : compartments(bands, plate_stations_m))
    for (const auto& [k, second] : of_kind) {
      const auto first = of_kind.find(k - 1), third = of_kind.find(k + 1), fourth = of_kind.find(k + 2);
      if (first == of_kind.end() || third == of_kind.end() || fourth == of_kind.end()) continue;
      const std::array<double, 3> w = quadratic_weights(
          {first->second.station_m(), third->second.station_m(), fourth->second.station_m()}, second.station_m());
      out.push_back({{first->second.planes, second.planes, third->second.planes, fourth->second.planes},
                     {-w[0], 1.0, -w[1], -w[2]},
                     sigma_rad});
    }
  return out;
}

}  // namespace tunnelmap
