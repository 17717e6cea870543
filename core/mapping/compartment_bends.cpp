#include "core/mapping/compartment_bends.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <Eigen/Core>
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

std::vector<std::vector<EvenTurn>> compartment_even_turns(const std::vector<WallBand>& bands,
                                                          std::vector<double> plate_stations_m, double sigma_rad) {
  std::sort(plate_stations_m.begin(), plate_stations_m.end());
  std::vector<std::vector<EvenTurn>> out;
  for (const auto& [kind, of_kind] : compartments(bands, plate_stations_m)) {
    std::vector<EvenTurn> turns;
    for (const auto& [k, middle] : of_kind) {
      const auto before = of_kind.find(k - 1), after = of_kind.find(k + 1);
      if (before == of_kind.end() || after == of_kind.end()) continue;
      const double s_a = before->second.station_m(), s_b = middle.station_m(), s_c = after->second.station_m();
      const double weight_c = (s_b - s_a) / (s_c - s_a);
      turns.push_back({k, {{before->second.planes, middle.planes, after->second.planes}, {weight_c - 1.0, 1.0, -weight_c}, sigma_rad}});
    }
    if (!turns.empty()) out.push_back(std::move(turns));
  }
  return out;
}

namespace {

// The tie's departure at `planes` (radians, as a vector; core/solvers/pose_graph.h).
Eigen::Vector3d departure(const PlaneBend& tie, const std::vector<GraphPlane>& planes) {
  std::vector<Eigen::Vector3d> means;
  for (const std::vector<int>& stretch : tie.stretches) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int plane : stretch) mean += planes[static_cast<std::size_t>(plane)].normal;
    means.push_back(mean / static_cast<double>(stretch.size()));
  }
  return bend_departure(means, tie.weights);
}

}  // namespace

std::vector<PlaneBend> even_turns_where_the_map_turns_evenly(const std::vector<std::vector<EvenTurn>>& turns,
                                                             const std::vector<GraphPlane>& planes) {
  constexpr int kReach = 2;  // compartments either side in the neighbourhood
  std::vector<PlaneBend> out;
  for (const std::vector<EvenTurn>& of_kind : turns) {
    std::vector<Eigen::Vector3d> departures;
    for (const EvenTurn& t : of_kind) departures.push_back(departure(t.tie, planes));
    for (std::size_t i = 0; i < of_kind.size(); ++i) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int count = 0;
      for (std::size_t j = 0; j < of_kind.size(); ++j)
        if (std::abs(of_kind[j].compartment - of_kind[i].compartment) <= kReach) sum += departures[j], ++count;
      if (sum.norm() / count < of_kind[i].tie.sigma_rad) out.push_back(of_kind[i].tie);
    }
  }
  return out;
}

}  // namespace tunnelmap
