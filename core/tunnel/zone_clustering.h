#pragma once
// Step 4 of tunnel detection: zone positions along a fixed wall normal, clustered in 1D.
#include <vector>

#include "core/tunnel/tunnel_map.h"
#include "core/tunnel/zone_support.h"

namespace tunnelmap {

struct ZonePosition {
  double offset_m = 0.0;  // plane offset with the wall's common normal: -(n . centroid)
  int points = 0;
};

// Single-linkage clustering of the offsets: sorted, a gap larger than `gap_m` starts a new
// cluster. Only planes with >= `anchor_points` points link clusters: a smaller plane joins the
// nearest cluster within `gap_m`, so a chain of small noisy far planes cannot merge two zones
// (a 6 mm plate step with 4 mm gaps); small planes near no anchor cluster among themselves.
// Each cluster's offset is the point-weighted mean (planes with 0 points weigh 1).
// Returned outermost first (largest offset = furthest from the tunnel inside).
std::vector<ZoneCluster> cluster_zone_positions(std::vector<ZonePosition> positions, double gap_m,
                                               int anchor_points = 0);
// The same, written into `out` (its buffer reused). Sorts `positions` in place (outermost first).
void cluster_zone_positions(std::vector<ZonePosition>& positions, double gap_m, int anchor_points,
                            std::vector<ZoneCluster>& out);
// The buffers of the clustering, kept by the caller (TunnelScratch): with them and a reused
// `out`, clustering frame after frame allocates nothing in the steady state.
struct ZoneClusterScratch {
  std::vector<int> cluster_of;              // per position
  std::vector<double> lo, hi;               // offset range of each cluster's linking planes
  std::vector<double> weighted_sum, weight;  // per cluster, for the point-weighted mean
};
// The same with gap and anchor support taken at each plane's offset (zone_support.h): two
// neighbouring positions are split by the gap at the outer one, a plane is an anchor when it has
// scaling.support_at(its offset) points. Unscaled (both references 0) it is the one above.
void cluster_zone_positions(std::vector<ZonePosition>& positions, const ZoneScaling& scaling,
                            std::vector<ZoneCluster>& out, ZoneClusterScratch& scratch);
// The same with scratch of its own: allocates it on every call.
void cluster_zone_positions(std::vector<ZonePosition>& positions, const ZoneScaling& scaling,
                            std::vector<ZoneCluster>& out);

// Index into `clusters` of the outermost cluster with at least `min_points` points, or -1.
int outermost_supported_cluster(const std::vector<ZoneCluster>& clusters, int min_points);
// The same with the support each cluster needs at its own offset.
int outermost_supported_cluster(const std::vector<ZoneCluster>& clusters, const ZoneScaling& scaling);

// Symmetric zone prior (paper 2.2: "all zones are symmetric about the tunnel axis", "zones
// associated with each wall are a plane shifted by small distances"). The edge-to-middle step a
// wall shows: its outermost supported cluster minus its largest (middle-plate) cluster, when
// these differ and 0 < step <= max_step_m; else 0.
double observed_edge_step(const std::vector<ZoneCluster>& clusters, int min_points, double max_step_m);

// True when exactly one cluster has >= min_points: the wall's edge bands were not seen (e.g.
// at a grazing angle from close by) and that cluster is taken as its middle plate.
bool single_supported_zone(const std::vector<ZoneCluster>& clusters, int min_points);

}  // namespace tunnelmap
