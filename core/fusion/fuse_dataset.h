#pragma once
// Fuses a posed dataset: resolves every frame's camera pose (explicit pose, else forward
// kinematics of its joints), runs the per-frame tunnel detection (with the sequence context),
// integrates all frames into one sparse TSDF volume (or, on request, the dense one over the
// data's bounding box, kept for comparison) and merges the per-frame maps in the world frame.
// Mesh extraction needs VTK and lives in mesh/ (extract_mesh), outside the core.
#include <functional>
#include <memory>
#include <vector>

#include "core/io/dataset.h"
#include "core/kinematics/frame_pose.h"
#include "core/mapping/multi_scan_map.h"
#include "core/mapping/pose_refinement.h"
#include "core/mapping/station_map.h"
#include "core/fusion/lattice_heading.h"
#include "core/fusion/sparse_tsdf_volume.h"
#include "core/fusion/tsdf_volume.h"
#include "core/params/parameters.h"
#include "core/util/stage_timer.h"

namespace tunnelmap {

struct FusedFrame {
  int index = 0;
  PoseSource pose_source = PoseSource::None;
  Eigen::Isometry3d camera_to_world = Eigen::Isometry3d::Identity();  // refined (fused with)
  Eigen::Isometry3d given_camera_to_world = Eigen::Isometry3d::Identity();  // explicit or FK
  TunnelMap map;  // per-frame detection, camera frame
  int pose_group = 0;
};

struct FuseSettings {
  bool prefer_joints = false;  // use FK even where a frame has an explicit pose
  bool detect = true;          // per-frame tunnel detection + merged map
  bool refine_poses = true;    // correct each pose group against the map (needs detect)
  int threads = 0;             // TSDF integration threads (0 = all cores, at most 8)
  bool dense = false;          // the dense volume over the data's box instead of the sparse one
  std::function<void(const std::string& stage, int done, int total)> progress;
  // After each frame integrated into the sparse volume (after `progress`), on the fusing thread
  // with no integration running: a live view may read the volume (mesh it) without a lock.
  std::function<void(const SparseTsdfVolume& volume, int done, int total)> integrated;
};

struct FusionResult {
  std::unique_ptr<SparseTsdfVolume> volume;      // null when settings.dense
  std::unique_ptr<TsdfVolume> dense_volume;      // only when settings.dense
  LatticeHeading lattice;  // the sparse volume's lattice, fixed before the first frame
  std::vector<FusedFrame> frames;
  MultiScanMap merged;
  StationMap stations;  // the map along the tunnel: sections that change (`fuse --map`)
  PoseRefinement refinement;  // per pose group correction (ran == false: not refined)
  StageTimings timings_ms;  // "load+detect", "map" (refinement + station map), "integrate", "total"
};

// InputError (naming dataset.json and the frame) for a frame without pose and joints.
FusionResult fuse_dataset(const Dataset& dataset, const Parameters& params,
                          const FuseSettings& settings = FuseSettings());

}  // namespace tunnelmap
