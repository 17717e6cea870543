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
#include "core/mapping/pose_refinement.h"
#include "core/params/parameters.h"
#include "ui/scene/scene_geometry.h"

namespace tunnelmap {
// Declared only: their headers bring TBB, whose `emit` clashes with Qt's keyword in the
// widgets that include this header.
class SparseTsdfVolume;
struct TriangleMesh;
}  // namespace tunnelmap

namespace tunnelmap::ui {

constexpr double kFusedFrustumDepthM = 0.3;  // depth of the drawn camera frusta

// One arm pose (pose group) of the fused sequence, placed by its first frame.
struct FusedPoseGroup {
  int group = 0;
  std::vector<int> frames;
  bool rescan = false;
  std::string message;                      // "ok" or "move and rescan: <reason>"
  Eigen::Isometry3d fused_pose = Eigen::Isometry3d::Identity();  // camera to world, fused with
  Eigen::Isometry3d given_pose = Eigen::Isometry3d::Identity();  // forward kinematics / explicit
  bool corrected = false;                   // pose refinement gave it a correction
  PoseCorrection correction;
};

struct FusedScene {
  scene::SceneGeometry geometry;  // world frame, at the fused poses; cloud and planes empty
  // The same mesh with the frusta and the merged map at the given (forward-kinematics) poses,
  // built on the worker so that switching between the two only swaps inputs.
  scene::SceneGeometry given_geometry;
  MultiScanMap merged;
  bool refined = false;  // the poses were refined: the two geometries differ
  std::vector<FusedPoseGroup> groups;
  int frames = 0;
  int frusta = 0;  // one per pose group
  long long triangles = 0;
  double fuse_ms = 0.0, mesh_ms = 0.0;
};

struct FusionCancelled : std::runtime_error {
  FusionCancelled() : std::runtime_error("fusion cancelled") {}
};

// Told the volume after each frame integrated (FuseSettings::integrated), on the worker.
using VolumeWatcher = std::function<void(const SparseTsdfVolume& volume, int done, int total)>;

// `progress(done, total)` after each frame of each pass; throws FusionCancelled once `cancel`
// is set (checked at every progress step). InputError for frames without pose or joints.
// `refine_poses` false fuses at the given poses (FuseSettings::refine_poses). `integrated`
// sees the growing volume (the fused view's preview mesh, ui/fusion_preview.h).
FusedScene build_fused_scene(const Dataset& dataset, const Parameters& params,
                             const std::function<void(int, int)>& progress, const std::atomic<bool>& cancel,
                             bool refine_poses = true, const VolumeWatcher& integrated = {});

// The fused mesh as the 3D view's mesh layer takes it (world frame; a long one in pieces with
// level of detail): the final mesh and every preview go through here.
vtkSmartPointer<vtkPolyData> fused_mesh_polydata(const TriangleMesh& mesh);

}  // namespace tunnelmap::ui
