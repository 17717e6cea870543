#include "bench/plane_quality.h"

namespace tunnelmap::bench {

SegmentationOptions bench_scoring() {
  SegmentationOptions o;
  o.overlap = 0.5;
  return o;
}

void set_plane_counters(benchmark::State& state, const NamedFrame& frame, const PlaneSegments& planes) {
  state.counters["planes"] = static_cast<double>(planes.planes.size());
  if (frame.surface_id.empty()) return;
  const SegmentationScore s = score_segmentation(planes, frame.surface_id, bench_scoring());
  state.counters["recall"] = s.recall();
  state.counters["precision"] = s.precision();
  state.counters["true_surfaces"] = static_cast<double>(s.surfaces);
}

}  // namespace tunnelmap::bench
