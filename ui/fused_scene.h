#pragma once
// Processing > Fuse sequence: a posed dataset fused into one TSDF mesh and one merged tunnel map
// (core/fusion + mesh/), turned into scene geometry in the WORLD frame: the mesh, the merged
// map's boundary and zones, one camera frustum per arm pose. Runs on a worker thread.
#include <atomic>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/io/dataset.h"
#include "core/mapping/multi_scan_map.h"
#include "core/params/parameters.h"
#include "ui/scene/scene_geometry.h"

namespace tunnelmap::ui {

struct FusedScene {
  scene::SceneGeometry geometry;  // world frame; cloud and planes empty
  MultiScanMap merged;
  int frames = 0;
  int frusta = 0;  // one per pose group
  long long triangles = 0;
  double fuse_ms = 0.0, mesh_ms = 0.0;
};

struct FusionCancelled : std::runtime_error {
  FusionCancelled() : std::runtime_error("fusion cancelled") {}
};

// `progress(done, total)` after each frame of each pass; throws FusionCancelled once `cancel`
// is set (checked at every progress step). InputError for frames without pose or joints.
FusedScene build_fused_scene(const Dataset& dataset, const Parameters& params,
                             const std::function<void(int, int)>& progress, const std::atomic<bool>& cancel);

}  // namespace tunnelmap::ui
