#include "ui/fused_scene.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>

#include "core/fusion/fuse_dataset.h"
#include "mesh/tsdf_mesher.h"
#include "ui/scene/frustum_polydata.h"
#include "ui/scene/tunnel_polydata.h"

namespace tunnelmap::ui {

namespace {

vtkSmartPointer<vtkPolyData> mesh_polydata(const TriangleMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].x(), mesh.vertices[i].y(), mesh.vertices[i].z());
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (mesh.colors.size() == mesh.vertices.size()) {
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetName("RGB");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(static_cast<vtkIdType>(mesh.colors.size()));
    for (std::size_t i = 0; i < mesh.colors.size(); ++i)
      for (int c = 0; c < 3; ++c) colors->SetTypedComponent(static_cast<vtkIdType>(i), c, mesh.colors[i][c]);
    poly->GetPointData()->SetScalars(colors);
  }
  if (mesh.normals.size() == mesh.vertices.size()) {
    auto normals = vtkSmartPointer<vtkFloatArray>::New();
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.normals.size()));
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
      normals->SetTuple3(static_cast<vtkIdType>(i), mesh.normals[i].x(), mesh.normals[i].y(), mesh.normals[i].z());
    poly->GetPointData()->SetNormals(normals);
  }
  return poly;
}

// One frustum (camera frame) per pose, moved into the world frame, in one polydata.
vtkSmartPointer<vtkPolyData> frusta_polydata(const Intrinsics& k, const std::vector<PoseGroupStatus>& poses) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& pose : poses) {
    auto one = scene::make_frustum_polydata(k, 0.3);
    const vtkIdType offset = points->GetNumberOfPoints();
    for (vtkIdType i = 0; i < one->GetNumberOfPoints(); ++i) {
      double p[3];
      one->GetPoint(i, p);
      const Eigen::Vector3d w = pose.camera_to_world * Eigen::Vector3d(p[0], p[1], p[2]);
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

}  // namespace

FusedScene build_fused_scene(const Dataset& dataset, const Parameters& params,
                             const std::function<void(int, int)>& progress, const std::atomic<bool>& cancel) {
  const int n = static_cast<int>(dataset.frames.size());
  FuseSettings settings;
  settings.progress = [&](const std::string& stage, int done, int) {
    if (cancel.load()) throw FusionCancelled();
    if (progress) progress(done + (stage == "integrate" ? n : 0), 2 * n);
  };
  FusionResult r = fuse_dataset(dataset, params, settings);
  if (cancel.load()) throw FusionCancelled();
  MeshStats ms;
  const TriangleMesh mesh = extract_mesh(*r.volume, params.get_int("fusion.min_weight"), &ms);

  FusedScene out;
  out.frames = n;
  out.fuse_ms = r.timings_ms.count("total") ? r.timings_ms.at("total") : 0.0;
  out.mesh_ms = ms.milliseconds;
  out.triangles = static_cast<long long>(mesh.triangles.size());
  auto& g = out.geometry;
  g.cloud = vtkSmartPointer<vtkPolyData>::New();  // no single frame's cloud in the world view
  g.planes = vtkSmartPointer<vtkPolyData>::New();
  g.mesh = mesh_polydata(mesh);
  g.boundary = scene::make_boundary_polydata(r.merged.map);
  g.traversable = scene::make_zones_polydata(r.merged.map, ZoneKind::Traversable);
  g.forbidden = scene::make_zones_polydata(r.merged.map, ZoneKind::Forbidden);
  g.frustum = frusta_polydata(dataset.intrinsics, r.merged.poses);
  g.map = r.merged.map;
  out.frusta = static_cast<int>(r.merged.poses.size());
  out.merged = std::move(r.merged);
  return out;
}

}  // namespace tunnelmap::ui
