#pragma once
// Plane recall/precision counters against the simulator's true surfaces, the same score for
// TunnelMap and every peer (core/evaluation/segmentation_metrics.h).
#include <benchmark/benchmark.h>

#include "bench/bench_frames.h"
#include "core/evaluation/segmentation_metrics.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap::bench {

// A plane is correct when a majority (> 50 %) of its pixels lie on one true surface; a true
// surface of >= 3000 px (~1 % of VGA, the evaluation's minimum) is found when a correct plane
// lies on it. recall = found / counted surfaces, precision = correct / all planes.
SegmentationOptions bench_scoring();

// Sets "planes" always, and "recall" / "precision" on simulated frames.
void set_plane_counters(benchmark::State& state, const NamedFrame& frame, const PlaneSegments& planes);

}  // namespace tunnelmap::bench
