#include "core/mapping/compartment_bends.h"

#include <algorithm>
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

}  // namespace

std::vector<PlaneBend> compartment_bends(const std::vector<WallBand>& bands, std::vector<double> plate_stations_m,
                                         double sigma_rad) {
  std::sort(plate_stations_m.begin(), plate_stations_m.end());
  std::vector<PlaneBend> out;
  for (const auto& [kind, of_kind] : compartments(bands, plate_stations_m))
    for (const auto& [k, middle] : of_kind) {
      const auto before = of_kind.find(k - 1), after = of_kind.find(k + 1);
      if (before == of_kind.end() || after == of_kind.end()) continue;
      const double s_a = before->second.station_m(), s_b = middle.station_m(), s_c = after->second.station_m();
      const double weight_c = (s_b - s_a) / (s_c - s_a);
      out.push_back({before->second.planes, middle.planes, after->second.planes, 1.0 - weight_c, weight_c, sigma_rad});
    }
  return out;
}

}  // namespace tunnelmap
