#include "core/tunnel/zone_clustering.h"

#include <algorithm>

namespace tunnelmap {

std::vector<ZoneCluster> cluster_zone_positions(std::vector<ZonePosition> positions, double gap_m,
                                               int anchor_points) {
  std::vector<ZoneCluster> out;
  cluster_zone_positions(positions, gap_m, anchor_points, out);
  return out;
}

void cluster_zone_positions(std::vector<ZonePosition>& positions, double gap_m, int anchor_points,
                            std::vector<ZoneCluster>& out) {
  ZoneScaling fixed;
  fixed.min_points = anchor_points;
  fixed.gap_m = gap_m;
  cluster_zone_positions(positions, fixed, out);
}

void cluster_zone_positions(std::vector<ZonePosition>& positions, const ZoneScaling& scaling,
                            std::vector<ZoneCluster>& out) {
  ZoneClusterScratch scratch;
  cluster_zone_positions(positions, scaling, out, scratch);
}

void cluster_zone_positions(std::vector<ZonePosition>& positions, const ZoneScaling& scaling,
                            std::vector<ZoneCluster>& out, ZoneClusterScratch& scratch) {
  std::sort(positions.begin(), positions.end(),
            [](const ZonePosition& a, const ZonePosition& b) { return a.offset_m > b.offset_m; });
  const size_t n = positions.size();
  std::vector<int>& cluster_of = scratch.cluster_of;
  std::vector<double>& lo = scratch.lo;
  std::vector<double>& hi = scratch.hi;
  std::vector<double>& weighted_sum = scratch.weighted_sum;
  std::vector<double>& weight = scratch.weight;
  cluster_of.assign(n, -1);
  lo.clear();
  hi.clear();
  // Single linkage over the planes with index list `which` (sorted, outermost first).
  auto link = [&](auto&& is_member) {
    int last = -1;
    for (size_t i = 0; i < n; ++i) {
      if (!is_member(i)) continue;
      if (last < 0 || positions[last].offset_m - positions[i].offset_m >
                          scaling.gap_at(positions[last].offset_m)) {
        lo.push_back(positions[i].offset_m);
        hi.push_back(positions[i].offset_m);
      }
      cluster_of[i] = static_cast<int>(lo.size()) - 1;
      lo.back() = positions[i].offset_m;
      last = static_cast<int>(i);
    }
  };
  // 1. Anchors link zones; 2. small planes join the nearest anchor cluster within the gap
  // (they cannot bridge two zones); 3. small planes left over link among themselves.
  link([&](size_t i) { return positions[i].points >= scaling.support_at(positions[i].offset_m); });
  const size_t anchored = lo.size();
  for (size_t i = 0; i < n; ++i) {
    if (cluster_of[i] >= 0) continue;
    const double x = positions[i].offset_m;
    double best = scaling.gap_at(x);
    for (size_t c = 0; c < anchored; ++c) {
      const double d = x > hi[c] ? x - hi[c] : (x < lo[c] ? lo[c] - x : 0.0);
      if (d <= best) best = d, cluster_of[i] = static_cast<int>(c);
    }
  }
  link([&](size_t i) { return cluster_of[i] < 0; });

  out.assign(lo.size(), ZoneCluster());
  weighted_sum.assign(lo.size(), 0.0);
  weight.assign(lo.size(), 0.0);
  for (size_t i = 0; i < n; ++i) {
    const int c = cluster_of[i];
    const double w = std::max(1, positions[i].points);  // the point-weighted mean
    weighted_sum[c] += w * positions[i].offset_m;
    weight[c] += w;
    out[c].planes += 1;
    out[c].points += positions[i].points;
  }
  for (size_t c = 0; c < out.size(); ++c) out[c].offset_m = weighted_sum[c] / weight[c];
  std::sort(out.begin(), out.end(),
            [](const ZoneCluster& a, const ZoneCluster& b) { return a.offset_m > b.offset_m; });
}

int outermost_supported_cluster(const std::vector<ZoneCluster>& clusters, int min_points) {
  int best = -1;
  for (size_t i = 0; i < clusters.size(); ++i)
    if (clusters[i].points >= min_points &&
        (best < 0 || clusters[i].offset_m > clusters[best].offset_m))
      best = static_cast<int>(i);
  return best;
}

int outermost_supported_cluster(const std::vector<ZoneCluster>& clusters, const ZoneScaling& scaling) {
  int best = -1;
  for (size_t i = 0; i < clusters.size(); ++i)
    if (clusters[i].points >= scaling.support_at(clusters[i].offset_m) &&
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
