#include "ui/fused_scene.h"

#include "ui/scene/mesh_polydata.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include "core/fusion/fuse_dataset.h"
#include "core/fusion/fusion_options.h"
#include "core/tunnel/tunnel_options.h"
#include "mesh/tsdf_mesher.h"
#include "ui/mesh_level_of_detail.h"
#include "ui/scene/frustum_polydata.h"
#include "ui/scene/tunnel_polydata.h"

namespace tunnelmap::ui {

namespace {

// One frustum (camera frame) per pose, moved into the world frame, in one polydata.
vtkSmartPointer<vtkPolyData> frusta_polydata(const Intrinsics& k, const std::vector<Eigen::Isometry3d>& poses) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& pose : poses) {
    auto one = scene::make_frustum_polydata(k, kFusedFrustumDepthM);
    const vtkIdType offset = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < one->GetNumberOfPoints(); ++i) {
      double p[3];
      one->GetPoint(i, p);
      const Eigen::Vector3d w = pose * Eigen::Vector3d(p[0], p[1], p[2]);
      points->InsertNextPoint(w.x(), w.y(), w.z());
    }
    for (vtkCellArray* cells : {one->GetLines(), one->GetPolys()}) {
      if (!cells) continue;
      vtkIdType count = 0;
      const vtkIdType* ids = nullptr;
      for (cells->InitTraversal(); cells->GetNextCell(count, ids);) {
        std::vector<vtkIdType> moved(ids, ids + count);
        for (auto& id : moved) id += offset;
        lines->InsertNextCell(count, moved.data());
      }
    }
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(lines);
  return poly;
}

// The map-dependent layers of `g` from `merged`, and one frustum per pose group.
void set_pose_layers(scene::SceneGeometry& g, const MultiScanMap& merged, const Intrinsics& k,
                     const std::vector<Eigen::Isometry3d>& group_poses) {
  g.boundary = scene::make_boundary_polydata(merged.map);
  g.traversable = scene::make_zones_polydata(merged.map, ZoneKind::Traversable);
  g.forbidden = scene::make_zones_polydata(merged.map, ZoneKind::Forbidden);
  g.frustum = frusta_polydata(k, group_poses);
  g.map = merged.map;
}

}  // namespace

FusedScene build_fused_scene(const Dataset& dataset, const Parameters& params,
                             const std::function<void(int, int)>& progress, const std::atomic<bool>& cancel,
                             bool refine_poses, const VolumeWatcher& integrated) {
  const int n = static_cast<int>(dataset.frames.size());
  FuseSettings settings;
  settings.refine_poses = refine_poses;
  settings.integrated = integrated;
  settings.progress = [&](const std::string& stage, int done, int) {
    if (cancel.load()) throw FusionCancelled();
    if (progress) progress(done + (stage == "integrate" ? n : 0), 2 * n);
  };
  FusionResult r = fuse_dataset(dataset, params, settings);
  if (cancel.load()) throw FusionCancelled();
  MeshStats ms;
  const TriangleMesh mesh = extract_mesh(*r.volume, fusion_options(params).min_weight, &ms);

  FusedScene out;
  out.frames = n;
  out.fuse_ms = r.timings_ms.count("total") ? r.timings_ms.at("total") : 0.0;
  out.mesh_ms = ms.milliseconds;
  out.triangles = static_cast<long long>(mesh.triangles.size());
  out.refined = r.refinement.ran;

  // Per pose group: where its first frame was fused and where the arm put it.
  std::vector<Eigen::Isometry3d> fused_poses, given_poses;
  for (const auto& p : r.merged.poses) {
    FusedPoseGroup fg;
    fg.group = p.group;
    fg.frames = p.frames;
    fg.rescan = p.rescan;
    fg.message = p.message;
    const FusedFrame* first = p.frames.empty() ? nullptr : &r.frames[static_cast<std::size_t>(p.frames.front())];
    fused_poses.push_back(first ? first->camera_to_world : p.camera_to_world);
    given_poses.push_back(first ? first->given_camera_to_world : p.camera_to_world);
    fg.fused_pose = fused_poses.back();
    fg.given_pose = given_poses.back();
    for (const auto& c : r.refinement.groups)
      if (c.group == p.group) {
        fg.corrected = true;
        fg.correction = c;
      }
    out.groups.push_back(std::move(fg));
  }

  auto& g = out.geometry;
  g.cloud = vtkSmartPointer<vtkPolyData>::New();  // no single frame's cloud in the world view
  g.planes = vtkSmartPointer<vtkPolyData>::New();
  g.mesh = fused_mesh_polydata(mesh);
  set_pose_layers(g, r.merged, dataset.intrinsics, fused_poses);
  out.given_geometry = g;
  if (out.refined) {
    // The merged map as the per-frame detections place it at the given poses (the mesh stays:
    // re-integrating is a fusion of its own).
    std::vector<ScanInput> scans;
    std::vector<int> groups;
    for (const auto& f : r.frames) {
      scans.push_back({f.map, f.given_camera_to_world, f.index});
      groups.push_back(f.pose_group);
    }
    const MultiScanMap given = merge_scans(scans, groups, tunnel_options(params).zone_cluster_m);
    set_pose_layers(out.given_geometry, given, dataset.intrinsics, given_poses);
  }
  out.frusta = static_cast<int>(r.merged.poses.size());
  out.merged = std::move(r.merged);
  return out;
}

vtkSmartPointer<vtkPolyData> fused_mesh_polydata(const TriangleMesh& mesh) {
  return with_level_of_detail(scene::mesh_polydata(mesh));  // a long girder: pieces and overview
}

}  // namespace tunnelmap::ui
