#include "bench/plane_quality.h"

#include "core/normals/cloud_builder.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap::bench {

SegmentationOptions bench_scoring() {
  const GrowOptions grow = grow_options(Parameters());
  return SegmentationOptions::by_size(grow.min_points, grow.min_area_m2);
}

void set_plane_counters(benchmark::State& state, const NamedFrame& frame, const PlaneSegments& planes) {
  state.counters["planes"] = static_cast<double>(planes.planes.size());
  if (frame.surface_id.empty()) return;
  // The surfaces' visible areas come from the frame's own points (the default cloud range),
  // the same for every method scored.
  OrganizedCloud cloud;
  build_cloud(frame.frame, cloud_options(Parameters()), cloud);
  const SegmentationScore s = score_segmentation(planes, frame.surface_id, cloud, bench_scoring());
  state.counters["recall"] = s.recall();
  state.counters["precision"] = s.precision();
  state.counters["true_surfaces"] = static_cast<double>(s.surfaces);
}

}  // namespace tunnelmap::bench
