#pragma once
// A posed dataset mapped end to end, shared by `map` and `render --map`: every frame detected by
// the run engine (in order, a bounded number in flight), its wall samples kept, then the poses refined
// against the map and the station map built (map_posed_sequence).
#include <functional>
#include <string>
#include <vector>

#include "core/io/dataset.h"
#include "core/mapping/mapping_notes.h"
#include "core/mapping/posed_sequence.h"
#include "core/pipeline/pipeline.h"

namespace tunnelmap {

struct DatasetMapping {
  std::vector<TunnelMap> maps;           // per frame, with the map's context applied
  std::vector<std::string> sources;      // per frame, as the frame names itself
  std::vector<std::size_t> plane_counts;
  std::vector<StageTimings> timings;     // per frame, the pipeline's stage times
  MappedSequence mapped;
  MappingNotes notes;                    // what the user should be told about `mapped`
  double detect_ms = 0.0;                // all frames' pipeline totals
  double map_ms = 0.0;                   // everything beyond detection (wall samples, refinement, map)
  bool cancelled = false;                // `progress` asked to stop: no map was built
};

// The camera-to-world pose of every frame (explicit, else forward kinematics). InputError naming
// dataset.json when a frame has neither.
std::vector<Eigen::Isometry3d> dataset_poses(const Dataset& ds);

// Every frame's IMU gravity (camera frame), where the dataset gives one.
std::vector<std::optional<Eigen::Vector3d>> dataset_gravity(const Dataset& ds);

// `pipeline` carries the parameters and camera up; its world up is set to the dataset's.
// `progress(k)` is called after frame k-1 (k = 1..n); returning false stops the detection and
// returns a result marked cancelled. InputError for an empty dataset or a frame without a pose;
// a bad frame's InputError names it.
using MappingProgress = std::function<bool(std::size_t done)>;
DatasetMapping map_dataset(const Dataset& ds, Pipeline& pipeline, bool refine_poses,
                           const MappingProgress& progress = {});

}  // namespace tunnelmap
