#pragma once
// Plane recall/precision counters against the simulator's true surfaces, the same score for
// TunnelMap and every peer (core/evaluation/segmentation_metrics.h).
#include <benchmark/benchmark.h>

#include "bench/bench_frames.h"
#include "core/evaluation/segmentation_metrics.h"
#include "core/planes/plane_segment.h"

namespace tunnelmap::bench {

// The recall definition of docs/recall.md. A true surface counts when its visible part (pixels with a 3-D point
// inside the default cloud range) has at least grow.min_points pixels (40) and an area of at
// least grow.min_area_m2 (0.004 m^2) on the surface -- PG&C's own minimum plane size, from the
// GrowOptions defaults. A detected plane is correct when more than 50 % of its pixels lie on
// one true surface, and that surface is then found. recall = found / counted surfaces,
// precision = correct / all planes.
SegmentationOptions bench_scoring();

// Sets "planes" always, and "recall" / "precision" / "true_surfaces" on simulated frames.
void set_plane_counters(benchmark::State& state, const NamedFrame& frame, const PlaneSegments& planes);

}  // namespace tunnelmap::bench
