#include "core/tunnel/zone_clustering.h"

#include <algorithm>

namespace tunnelmap {

std::vector<ZoneCluster> cluster_zone_positions(std::vector<ZonePosition> positions, double gap_m) {
  std::sort(positions.begin(), positions.end(),
            [](const ZonePosition& a, const ZonePosition& b) { return a.offset_m > b.offset_m; });
  std::vector<ZoneCluster> out;
  double weighted_sum = 0.0, weight = 0.0;
  auto close_cluster = [&]() {
    if (out.empty() || weight <= 0.0) return;
    out.back().offset_m = weighted_sum / weight;
    weighted_sum = weight = 0.0;
  };
  for (size_t i = 0; i < positions.size(); ++i) {
    if (i == 0 || positions[i - 1].offset_m - positions[i].offset_m > gap_m) {
      close_cluster();
      out.emplace_back();
    }
    const double w = std::max(1, positions[i].points);
    weighted_sum += w * positions[i].offset_m;
    weight += w;
    out.back().planes += 1;
    out.back().points += positions[i].points;
  }
  close_cluster();
  return out;
}

int outermost_supported_cluster(const std::vector<ZoneCluster>& clusters, int min_points) {
  int best = -1;
  for (size_t i = 0; i < clusters.size(); ++i)
    if (clusters[i].points >= min_points &&
        (best < 0 || clusters[i].offset_m > clusters[best].offset_m))
      best = static_cast<int>(i);
  return best;
}

double observed_edge_step(const std::vector<ZoneCluster>& clusters, int min_points, double max_step_m) {
  const int outer = outermost_supported_cluster(clusters, min_points);
  int dominant = -1;
  for (size_t i = 0; i < clusters.size(); ++i)
    if (clusters[i].points >= min_points &&
        (dominant < 0 || clusters[i].points > clusters[dominant].points))
      dominant = static_cast<int>(i);
  if (outer < 0 || dominant < 0 || outer == dominant) return 0.0;
  const double step = clusters[outer].offset_m - clusters[dominant].offset_m;
  return step > 0.0 && step <= max_step_m ? step : 0.0;
}

bool single_supported_zone(const std::vector<ZoneCluster>& clusters, int min_points) {
  int supported = 0;
  for (const ZoneCluster& c : clusters) supported += c.points >= min_points;
  return supported == 1;
}

}  // namespace tunnelmap
